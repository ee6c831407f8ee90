// startup: scene load + BVH build time and peak memory. Two tables: the generated atrium
// (`prism generate atrium`) read back from its GLB, pbrt-v4 and JSON files — file parsing,
// texture decoding and the BVH, as a user's `prism render atrium.glb` pays them — and a
// wavy height-field grid (procedural_grid.h), an easy BVH with no file, which isolates
// Embree's build. For the atrium, a separate `prism render FILE` process (this binary,
// 1280×720, 1 spp) gives the honest peak RSS of load + BVH + render: the "peak memory" its
// summary line reports (its own VmHWM, core/process_memory.h). Not wait4's ru_maxrss: Linux
// folds the spawning process' high-water mark into a child's at exec, so in `bench all`
// every child read as the bench process' own peak (672 MiB for a render that needs
// 165 MiB). This process' peaks are its own VmHWM too, a process-wide high-water mark:
// sizes run smallest first and each row reports the peak so far, so run this suite alone
// (`prism bench startup`) for clean peaks. Bytes per triangle come from the resident set
// (VmRSS) while the scene and its BVH are alive, which earlier peaks do not distort.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "prism/accel/embree_accel.h"
#include "prism/core/error.h"
#include "prism/core/process_memory.h"
#include "prism/render/prepared_scene.h"
#include "prism/render/renderer.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/loaders/atrium_generator.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/scene_writers.h"
#include "procedural_grid.h"
#include "suites.h"

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

double mib(std::optional<std::uint64_t> bytes) { return static_cast<double>(bytes.value_or(0)) / (1024.0 * 1024.0); }
double peak_rss_mib() { return mib(peak_resident_set_bytes()); }
double current_rss_mib() { return mib(resident_set_bytes()); }

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct ChildRun {
  double wall_s = 0.0;
  double peak_rss_mib = 0.0;
};

// Runs this executable (`prism render …`) with `args` and returns its wall time and the
// peak memory its summary line reports ("peak memory N MiB"); throws if it cannot start,
// fails, or reports no peak.
ChildRun run_prism_child(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string self = "prism";
  argv.push_back(self.data());
  std::vector<std::string> owned = args;
  for (auto& a : owned) argv.push_back(a.data());
  argv.push_back(nullptr);
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) throw Error("bench startup: cannot make a pipe for the prism child");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);  // dup2 clears O_CLOEXEC on stdout
  const auto start = Clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  if (spawned != 0) {
    close(out[0]);
    throw Error(fmt::format("bench startup: cannot start prism ({})", spawned));
  }
  std::string printed;
  char buffer[4096];
  for (ssize_t n; (n = read(out[0], buffer, sizeof buffer)) != 0;) {
    if (n > 0)
      printed.append(buffer, static_cast<std::size_t>(n));
    else if (errno != EINTR)
      break;
  }
  close(out[0]);
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) throw Error("bench startup: lost the prism child process");
  const double wall_s = seconds_since(start);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(fmt::format("bench startup: `prism {}` failed", fmt::join(args, " ")));
  const std::string key = "peak memory ";
  const auto at = printed.find(key);
  if (at == std::string::npos)
    throw Error(fmt::format("bench startup: `prism {}` reported no peak memory", fmt::join(args, " ")));
  return {wall_s, std::strtod(printed.c_str() + at + key.size(), nullptr)};
}

// The atrium at each size, written once per format into a scratch folder, then read back:
// load (parse + textures) and BVH build timed in this process, peak memory from a child
// render.
void add_atrium_table(SuiteReport& report, const BenchOptions& o, nlohmann::json& json_rows) {
  std::vector<std::size_t> sizes{1'000'000};
  if (o.quick) sizes = {loaders::kAtriumMinTriangles};
  if (o.full) sizes = {1'000'000, 10'000'000};
  const int width = o.quick ? 32 : 1280, height = o.quick ? 18 : 720;
  Table& t = report.add_table(
      fmt::format("generated atrium read from its files; child render: {}x{} spectral, 1 spp", width, height),
      {"triangles", "format", "file MiB", "load s", "BVH build s", "load + BVH s", "RSS with scene+BVH MiB",
       "render process wall s", "render process peak RSS MiB"});
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / fmt::format("prism-bench-startup-{}", static_cast<long>(getpid()));
  std::filesystem::create_directories(dir);
  struct Cleanup {
    std::filesystem::path dir;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } cleanup{dir};
  for (std::size_t target : sizes) {
    std::vector<std::filesystem::path> files;
    {
      const Scene generated = loaders::generate_atrium(target);
      files.push_back(dir / fmt::format("atrium-{}.glb", target));
      loaders::write_scene_glb(generated, files.back());
      if (target <= 1'000'000) {  // 10 M as text is gigabytes; GLB is the format for it
        files.push_back(dir / fmt::format("atrium-{}.pbrt", target));
        loaders::write_scene_pbrt(generated, files.back());
        files.push_back(dir / fmt::format("atrium-{}.json", target));
        loaders::write_scene_json(generated, files.back());
      }
    }
    for (const auto& file : files) {
      const double file_mib = static_cast<double>(std::filesystem::file_size(file)) / (1024.0 * 1024.0);
      const double rss_before = current_rss_mib();
      auto start = Clock::now();
      Scene scene = load_scene(file.string());
      const double load_s = seconds_since(start);
      const std::size_t tris = scene.triangle_count();
      double bvh_s = 0.0, resident = 0.0;
      {
        start = Clock::now();
        const EmbreeAccel accel(scene);
        bvh_s = seconds_since(start);
        resident = current_rss_mib() - rss_before;
      }
      scene = Scene{};
      std::vector<std::string> args{"render", file.string(), "--width", std::to_string(width), "--height",
                                    std::to_string(height), "--spp", "1", "-o", (dir / "out.exr").string()};
      if (o.threads > 0) {
        args.push_back("--threads");
        args.push_back(std::to_string(o.threads));
      }
      const ChildRun child = run_prism_child(args);
      const std::string format = file.extension().string().substr(1);
      t.add_row({static_cast<std::uint64_t>(tris), format, file_mib, load_s, bvh_s, load_s + bvh_s, resident,
                 child.wall_s, child.peak_rss_mib});
      json_rows.push_back({{"scene", "atrium"}, {"triangles", tris}, {"format", format}, {"file_mib", file_mib},
                           {"load_s", load_s}, {"bvh_s", bvh_s}, {"render_process_s", child.wall_s},
                           {"render_process_peak_rss_mib", child.peak_rss_mib}});
    }
  }
}

}  // namespace

SuiteReport run_startup_suite(const BenchOptions& o) {
  SuiteReport report{"startup"};
  nlohmann::json rows = nlohmann::json::array();
  add_atrium_table(report, o, rows);
  std::vector<std::size_t> sizes{1'000'000};
  if (o.quick) sizes = {10'000};
  if (o.full) sizes = {1'000'000, 10'000'000};
  const int width = o.quick ? 32 : 1280, height = o.quick ? 18 : 720;
  Table& t = report.add_table(
      fmt::format("generated grid scene; render: {}x{} spectral, 1 spp", width, height),
      {"triangles", "scene build s", "BVH build s", "build total s", "RSS before MiB", "RSS with BVH MiB",
       "peak after BVH MiB", "bytes/triangle (scene+BVH)", "render s", "restart s", "peak after render MiB"});
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
    rows.push_back({{"scene", "grid"}, {"triangles", tris}, {"scene_s", scene_s}, {"bvh_s", bvh_s}, {"restart_s", restart_s}, {"peak_rss_mib", peak_rss_mib()}});
  }
  report.data["rows"] = rows;
  report.notes.push_back("atrium: load = load_scene(FILE) (parsing, texture decoding, mesh checks); the child "
                         "`prism render FILE` pays load + BVH + render and its peak RSS is what a user sees");
  report.notes.push_back("grid: scene build = generating the mesh in memory (no file); render() copies the scene "
                         "(flatten_instances) and builds its own BVH, included in 'render s' and the last peak; "
                         "'restart s' renders a PreparedScene (geometry and BVH kept, as the viewer does on every "
                         "restart); peaks are this process' high-water mark so far");
  report.notes.push_back("issue 8 targets: 1M triangles load + BVH <= 1.5 s, peak <= 600 MB at 1280x720; 10M "
                         "triangles load and render within 8 GB (--full)");
  return report;
}

}  // namespace prism::bench
