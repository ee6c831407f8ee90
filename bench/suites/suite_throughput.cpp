// throughput: samples/s and Mrays/s at fixed spp, median of --repeat runs (min and max
// beside it show the machine's noise): the Cornell box, spectral and RGB; the generated
// 1 M-triangle atrium at 1280×720, spectral (textures, alpha-masked foliage, glass, gold,
// environment); and the material-test scene (spheres of every material: GGX conductors,
// rough and smooth dielectrics, coated), the glossy/dielectric case.
#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "prism/scene/builtin_scenes.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/atrium_generator.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {

SuiteReport run_throughput_suite(const BenchOptions& o) {
  SuiteReport report{"throughput"};
  const Scene scene = make_cornell_box();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 512);
  const int spp = o.spp > 0 ? o.spp : (o.quick ? 1 : 16);
  const int repeat = o.quick ? 1 : std::max(1, o.repeat);
  Table& t = report.add_table(fmt::format("Cornell box {}^2, {} spp, max depth 8, median of {} runs", size, spp, repeat),
                              {"mode", "samples/s (median)", "min", "max", "Mrays/s (median)", "rays/sample",
                               "shadow rays/sample", "samples/s / pbrt-v4 (quoted)"});
  nlohmann::json rows = nlohmann::json::array();
  for (TransportKind kind : {TransportKind::spectral, TransportKind::rgb}) {
    const RenderSettings settings = cornell_settings(size, spp, kind, o.threads);
    std::vector<double> sps, rps;
    RenderMeasurement last;
    for (int i = 0; i < repeat; ++i) {
      last = measure(render(scene, settings));
      sps.push_back(last.samples_per_second);
      rps.push_back(last.rays_per_second);
    }
    const double samples = static_cast<double>(spp) * size * size;
    const double med = median(sps);
    t.add_row({transport_label(settings), med, *std::min_element(sps.begin(), sps.end()),
               *std::max_element(sps.begin(), sps.end()), median(rps) * 1e-6, last.rays_per_sample,
               static_cast<double>(last.shadow_rays) / samples, med / 0.49e6});
    rows.push_back({{"mode", transport_label(settings)}, {"samples_per_s", sps}, {"rays_per_s", rps}});
  }
  report.data["rows"] = rows;

  // Larger and glossier scenes, spectral only (the default transport).
  struct OtherScene {
    std::string name;
    Scene scene;
    int width, height, spp;
  };
  std::vector<OtherScene> others;
  others.push_back({"atrium", loaders::generate_atrium(o.quick ? loaders::kAtriumMinTriangles : 1'000'000),
                    o.quick ? 32 : 1280, o.quick ? 18 : 720, o.spp > 0 ? o.spp : (o.quick ? 1 : 4)});
  others.push_back({"material-test", load_scene("material-test"), o.quick ? 16 : 512, o.quick ? 16 : 512,
                    o.spp > 0 ? o.spp : (o.quick ? 1 : 16)});
  Table& t2 = report.add_table(fmt::format("other scenes, spectral defaults, median of {} runs", repeat),
                               {"scene", "triangles", "image", "spp", "samples/s (median)", "min", "max",
                                "Mrays/s (median)", "rays/sample"});
  nlohmann::json other_rows = nlohmann::json::array();
  for (const OtherScene& other : others) {
    RenderSettings settings;
    settings.width = other.width;
    settings.height = other.height;
    settings.samples_per_pixel = other.spp;
    settings.threads = o.threads;
    std::vector<double> sps, rps;
    RenderMeasurement last;
    for (int i = 0; i < repeat; ++i) {
      last = measure(render(other.scene, settings));
      sps.push_back(last.samples_per_second);
      rps.push_back(last.rays_per_second);
    }
    t2.add_row({other.name, static_cast<std::uint64_t>(other.scene.triangle_count()),
                fmt::format("{}x{}", other.width, other.height), other.spp, median(sps),
                *std::min_element(sps.begin(), sps.end()), *std::max_element(sps.begin(), sps.end()),
                median(rps) * 1e-6, last.rays_per_sample});
    other_rows.push_back({{"scene", other.name}, {"triangles", other.scene.triangle_count()},
                          {"samples_per_s", sps}, {"rays_per_s", rps}});
  }
  report.data["other_scenes"] = other_rows;
  report.notes.push_back("pbrt-v4 on this machine (quoted from issue 8, not run here): 0.49 M samples/s, "
                         "2.05 M rays/s, 4.18 rays/sample");
  return report;
}

}  // namespace prism::bench
