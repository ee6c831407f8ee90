#pragma once
// Small synthetic scenes with known answers for integrator tests.
#include "prism/scene/scene.h"

namespace prism::test {

// A closed cube whose six inner faces are Lambertian with the given albedo and all emit
// radiance `emitted` towards the inside; the camera sits at the centre. Every ray then
// sees L = Le / (1 - albedo) exactly (the Neumann series of the rendering equation).
Scene make_emitting_enclosure(float albedo, float emitted);

// A 200 × 200 grey Lambertian floor (ρ = 0.5, flat spectrum) in the y = 0 plane, front
// face up, and a camera `eye_height` above its centre looking straight down (image up =
// +z) with the given field of view. No lights: tests add theirs.
Scene make_grey_floor_seen_from_above(float eye_height, float fov_degrees);

}  // namespace prism::test
