// display: a 4K scene-linear image through exposure + ACES (SDR sRGB 100 nit, and
// Rec.2020 1000-nit ST 2084) in prism::display and in OpenColorIO 2.1's CPU processor
// (its built-in ACES transforms, default optimisation, as `--ocio-config` would use it),
// same image, same run. OCIO's apply() runs on the calling thread, so it is timed on one
// thread and, for the like-for-like figure, on bands of rows in parallel. prism's exact
// double-precision path (reference_path, the pipeline before the float kernel) is timed on
// one thread beside it.
#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "prism/color/color_space.h"
#include "prism/core/parallel.h"
#include "prism/display/display_pipeline.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {
namespace {

namespace OCIO = OCIO_NAMESPACE;
using Clock = std::chrono::steady_clock;

// Luminance from 2^-8 to 2^8 (× mid grey) left to right, hue around the circle top to
// bottom, saturation rising with the row band: every ACES stage sees work.
ImageRgbF test_image(int width, int height) {
  ImageRgbF img{width, height, std::vector<float>(static_cast<std::size_t>(width) * height * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double level = 0.18 * std::exp2(16.0 * (x + 0.5) / width - 8.0);
      const double hue = 6.283185307179586 * (y + 0.5) / height, sat = 0.2 + 0.8 * ((y * 8 / height) % 2);
      float* p = &img.rgb[(static_cast<std::size_t>(y) * width + x) * 3];
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<float>(level * (1.0 + sat * 0.9 * std::cos(hue - c * 2.0943951023931953)));
    }
  return img;
}

OCIO::ConstCPUProcessorRcPtr ocio_processor(const Mat3& to_aces, const char* output_style,
                                            const char* display_style) {
  auto group = OCIO::GroupTransform::Create();
  auto matrix = OCIO::MatrixTransform::Create();
  double m44[16] = {0};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m44[r * 4 + c] = to_aces(r, c);
  m44[15] = 1.0;
  matrix->setMatrix(m44);
  group->appendTransform(matrix);
  for (const char* style : {output_style, display_style}) {
    auto b = OCIO::BuiltinTransform::Create();
    b->setStyle(style);
    group->appendTransform(b);
  }
  return OCIO::Config::CreateRaw()->getProcessor(group)->getDefaultCPUProcessor();
}

void ocio_apply(const OCIO::ConstCPUProcessorRcPtr& cpu, const ImageRgbF& in, std::vector<float>& out,
                bool parallel) {
  out = in.rgb;
  const std::size_t row = static_cast<std::size_t>(in.width) * 3;
  if (!parallel) {
    OCIO::PackedImageDesc desc(out.data(), in.width, in.height, 3);
    cpu->apply(desc);
    return;
  }
  parallel_for(static_cast<std::size_t>(in.height), 16, [&](std::size_t y0, std::size_t y1) {
    OCIO::PackedImageDesc desc(out.data() + y0 * row, in.width, static_cast<long>(y1 - y0), 3);
    cpu->apply(desc);
  });
}

template <class F>
double median_seconds(int repeat, F&& f) {
  std::vector<double> s;
  for (int i = 0; i < repeat; ++i) {
    const auto start = Clock::now();
    f();
    s.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  return median(s);
}

}  // namespace

SuiteReport run_display_suite(const BenchOptions& o) {
  SuiteReport report{"display"};
  const int width = o.quick ? 64 : 3840, height = o.quick ? 36 : 2160;
  const int repeat = o.quick ? 1 : std::max(1, o.repeat);
  const int threads = o.threads > 0 ? o.threads : ThreadLimit::hardware_threads();
  const ImageRgbF image = test_image(width, height);
  const color::ColorSpace& srgb = color::color_space("srgb");
  const double mpix = static_cast<double>(width) * height * 1e-6;

  struct Case {
    const char* name;
    display::OdtId odt;
    const char* output_style;
    const char* display_style;
  };
  const Case cases[] = {
      {"ACES SDR sRGB 100 nit", display::OdtId::srgb_100nit,
       "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0", "DISPLAY - CIE-XYZ-D65_to_sRGB"},
      {"ACES HDR Rec.2020 PQ 1000 nit", display::OdtId::rec2020_pq_1000nit,
       "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - HDR-VIDEO-1000nit-15nit-REC2020lim_1.1",
       "DISPLAY - CIE-XYZ-D65_to_REC.2100-PQ"},
  };
  Table& t = report.add_table(
      fmt::format("{}x{} float RGB, exposure EV100 0, median of {} runs; Mpixels/s", width, height, repeat),
      {"transform", "prism exact path 1 thread", "prism 1 thread", fmt::format("prism {} threads", threads),
       "OCIO 1 thread", fmt::format("OCIO {} threads", threads), "exact/OCIO (1 thread)", "prism/OCIO (1 thread)",
       fmt::format("prism/OCIO ({} threads)", threads), "max |code diff|"});
  nlohmann::json rows = nlohmann::json::array();
  for (const Case& c : cases) {
    display::DisplaySettings settings;
    settings.exposure_ev100 = 0.0;
    settings.odt = c.odt;
    const double scale = display::exposure_scale(settings, image, srgb);
    Mat3 to_aces = display::film_to_aces_matrix(srgb, 0.0);
    for (auto& row : to_aces.m)
      for (double& v : row) v *= scale;
    const auto cpu = ocio_processor(to_aces, c.output_style, c.display_style);

    display::DisplayImage shown;
    std::vector<float> ocio_out;
    double prism1, prism_all, prism_exact1;
    {
      // The double-precision reference (DisplaySettings::reference_path): the pipeline as it
      // was before the float block kernel, for the before/after figure in one run.
      const ThreadLimit one(1);
      display::DisplaySettings exact = settings;
      exact.reference_path = true;
      prism_exact1 = median_seconds(repeat, [&] { shown = display::apply_display_pipeline(image, srgb, exact); });
      prism1 = median_seconds(repeat, [&] { shown = display::apply_display_pipeline(image, srgb, settings); });
    }
    {
      const ThreadLimit all(threads);
      prism_all = median_seconds(repeat, [&] { shown = display::apply_display_pipeline(image, srgb, settings); });
    }
    const double ocio1 = median_seconds(repeat, [&] { ocio_apply(cpu, image, ocio_out, false); });
    double ocio_all;
    {
      const ThreadLimit all(threads);
      ocio_all = median_seconds(repeat, [&] { ocio_apply(cpu, image, ocio_out, true); });
    }
    const bool sdr = c.odt == display::OdtId::srgb_100nit;
    double max_diff = 0.0;
    for (std::size_t i = 0; i < ocio_out.size() && i < shown.code.size(); ++i) {
      const double oc = sdr ? std::clamp(ocio_out[i], 0.0f, 1.0f) : ocio_out[i];  // CTL clamps SDR, OCIO does not
      max_diff = std::max(max_diff, std::fabs(oc - shown.code[i]));
    }
    t.add_row({c.name, mpix / prism_exact1, mpix / prism1, mpix / prism_all, mpix / ocio1, mpix / ocio_all,
               ocio1 / prism_exact1, ocio1 / prism1, ocio_all / prism_all, max_diff});
    rows.push_back({{"transform", c.name}, {"prism_exact_1_thread_s", prism_exact1}, {"prism_1_thread_s", prism1},
                    {"prism_all_threads_s", prism_all}, {"ocio_1_thread_s", ocio1}, {"ocio_all_threads_s", ocio_all},
                    {"max_code_diff", max_diff}});
  }
  report.data["rows"] = rows;
  report.notes.push_back("prism's pipeline also returns display-linear nits beside the code values; OCIO returns "
                         "code values only. Target (issue 8): prism/OCIO >= 1");
  return report;
}

}  // namespace prism::bench
