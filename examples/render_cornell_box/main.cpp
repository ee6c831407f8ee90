// Rendering through Prism's C++ API, as a program that found the installed package with
// find_package(Prism) does: the built-in Cornell box, a few samples per pixel, written as
// a scene-linear OpenEXR in linear sRGB (Rec.709 primaries, D65), with its chromaticities.
//
//   render_cornell_box OUTPUT.exr [SIZE [SPP]]
#include <cstdio>
#include <exception>
#include <string>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/io/exr.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: render_cornell_box OUTPUT.exr [SIZE [SPP]]\n");
    return 2;
  }
  try {
    const prism::Scene scene = prism::make_cornell_box();
    prism::RenderSettings settings;
    settings.width = settings.height = argc > 2 ? std::stoi(argv[2]) : 64;
    settings.samples_per_pixel = argc > 3 ? std::stoi(argv[3]) : 4;
    const prism::RenderResult result = prism::render(scene, settings, prism::RenderHooks{});

    // The film holds means in result.film_space (CIE XYZ for a spectral render): to sRGB.
    const prism::color::ColorSpace& srgb = prism::color::color_space("srgb");
    const prism::Mat3 to_srgb = prism::color::conversion_matrix(result.film_space, srgb);
    prism::ImageRgbF image{result.film.width(), result.film.height(), {}};
    prism::Vec3d sum;
    for (std::size_t i = 0; i < result.film.pixel_count(); ++i) {
      const prism::Vec3d rgb = to_srgb * result.film.mean(i);
      sum += rgb;
      for (int c = 0; c < 3; ++c) image.rgb.push_back(static_cast<float>(rgb[c]));
    }
    const auto f = [](double v) { return static_cast<float>(v); };
    const prism::ExrChromaticities chromaticities{f(srgb.red.x),  f(srgb.red.y),  f(srgb.green.x), f(srgb.green.y),
                                                  f(srgb.blue.x), f(srgb.blue.y), f(srgb.white.x), f(srgb.white.y)};
    prism::write_exr(argv[1], image, chromaticities);
    const double n = static_cast<double>(result.film.pixel_count());
    std::printf("%s: %dx%d, %d spp, mean linear sRGB %.6g %.6g %.6g\n", argv[1], image.width, image.height,
                result.passes_done, sum.x / n, sum.y / n, sum.z / n);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_cornell_box: %s\n", e.what());
    return 1;
  }
}
