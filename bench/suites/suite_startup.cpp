// startup: scene build + BVH build time and peak memory for a generated large mesh (the
// atrium stand-in of procedural_grid.h), then one 1280×720 sample per pixel to include
// the renderer's own memory. Peak RSS is getrusage's ru_maxrss, a process-wide high-water
// mark: sizes run smallest first and each row reports the peak so far, so run this suite
// alone (`prism bench startup`) for clean peaks. Bytes per triangle come from the resident
// set (/proc/self/statm) while the scene and its BVH are alive, which earlier peaks do
// not distort.
#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "prism/accel/embree_accel.h"
#include "prism/render/prepared_scene.h"
#include "prism/render/renderer.h"
#include "procedural_grid.h"
#include "suites.h"

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

double current_rss_mib() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  statm >> size >> resident;
  return resident * 4096.0 / (1024.0 * 1024.0);
}

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

SuiteReport run_startup_suite(const BenchOptions& o) {
  SuiteReport report{"startup"};
  std::vector<std::size_t> sizes{1'000'000};
  if (o.quick) sizes = {10'000};
  if (o.full) sizes = {1'000'000, 10'000'000};
  const int width = o.quick ? 32 : 1280, height = o.quick ? 18 : 720;
  Table& t = report.add_table(
      fmt::format("generated grid scene; render: {}x{} spectral, 1 spp", width, height),
      {"triangles", "scene build s", "BVH build s", "build total s", "RSS before MiB", "RSS with BVH MiB",
       "peak after BVH MiB", "bytes/triangle (scene+BVH)", "render s", "restart s", "peak after render MiB"});
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t target : sizes) {
    const double rss_before = current_rss_mib();
    auto start = Clock::now();
    Scene scene = make_triangle_grid_scene(target);
    const double scene_s = seconds_since(start);
    const std::size_t tris = scene.triangle_count();
    double bvh_s = 0.0, peak_bvh = 0.0, resident = 0.0;
    {
      start = Clock::now();
      const EmbreeAccel accel(scene);
      bvh_s = seconds_since(start);
      peak_bvh = peak_rss_mib();
      resident = current_rss_mib();  // scene + BVH, whatever earlier peaks were
    }
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samples_per_pixel = 1;
    settings.threads = o.threads;
    start = Clock::now();
    render(scene, settings);
    const double render_s = seconds_since(start);
    // A viewer restart: the scene prepared once (flattened, BVH built), then one more
    // 1-spp render of it, which is what each camera/material/light edit costs.
    const PreparedScene prepared(scene);
    start = Clock::now();
    render(prepared, settings, RenderHooks{});
    const double restart_s = seconds_since(start);
    const double bytes_per_tri = (resident - rss_before) * 1024.0 * 1024.0 / static_cast<double>(tris);
    t.add_row({static_cast<std::uint64_t>(tris), scene_s, bvh_s, scene_s + bvh_s, rss_before, resident, peak_bvh, bytes_per_tri,
               render_s, restart_s, peak_rss_mib()});
    rows.push_back({{"triangles", tris}, {"scene_s", scene_s}, {"bvh_s", bvh_s}, {"restart_s", restart_s}, {"peak_rss_mib", peak_rss_mib()}});
  }
  report.data["rows"] = rows;
  report.notes.push_back("scene build = generating the mesh in memory (no file parsing: the loaders' `prism "
                         "generate atrium` does not exist yet); render() copies the scene (flatten_instances) "
                         "and builds its own BVH, included in 'render s' and the last peak; 'restart s' renders a "
                         "PreparedScene (geometry and BVH kept, as the viewer does on every restart)");
  report.notes.push_back("issue 8 targets: 1M triangles load + BVH <= 1.5 s, peak <= 600 MB at 1280x720; 10M "
                         "triangles load and render within 8 GB (--full)");
  return report;
}

}  // namespace prism::bench
