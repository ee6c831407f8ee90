#pragma once
// The first picture of a scene: the defaults `prism render` and `prism view` both start from,
// in one place, so that the same scene opens the same in both (docs/viewer.md, "The first
// picture"). Options the user gives override them one by one.
//   camera       the scene's chosen camera (its first, or --camera), the environment the scene's
//                own or the --environment override, which both commands apply before this
//   film         the scene's default size (the viewer fits its window to that aspect ratio)
//   path         the bounce limit and normal-map model the scene file asks for, else
//                PathSettings' defaults (a cap of 64 bounces, Russian roulette after 3)
//   transport    TransportSettings' defaults (spectral, 4 wavelengths, cosh sampling)
//   exposure     the scene camera's physical exposure (f-number, shutter, ISO) when it has
//                one, else the film metered by display/exposure_metering.h with `metering`
#include <optional>

#include "prism/display/exposure_metering.h"
#include "prism/render/film.h"
#include "prism/render/prepared_scene.h"
#include "prism/render/renderer.h"
#include "prism/scene/scene.h"

namespace prism {

struct FirstPicture {
  Camera camera;
  int width = 512, height = 512;
  PathSettings path;
  TransportSettings transport;
  std::optional<double> camera_ev100;  // the scene camera's EV100; none: metered
  display::MeteringSettings metering;
};

FirstPicture first_picture_defaults(const Scene& scene);

// The metered exposure of a rendered film (`prism render` without an exposure option): the
// film's means in `film_space`, which pixels see a surface from camera_coverage.h (one ray
// through each pixel's centre, traced on `scene`), metered by display/exposure_metering.h.
display::MeteredExposure meter_rendered_film(const PreparedScene& scene, const Film& film,
                                             const color::ColorSpace& film_space,
                                             const display::MeteringSettings& metering);

}  // namespace prism
