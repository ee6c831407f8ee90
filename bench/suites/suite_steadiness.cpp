// steadiness: what path regeneration buys the wavefront integrator. The same render with
// a fixed number of samples per pass, regeneration on (a finished path restarts at once
// with its pixel's next sample) and off (one wave per sample, the queue drains to the
// longest path). Reports the pass-time spread and how full the queues stay: live paths
// per step (added across the tiles, step by step) as a fraction of the pixels.
#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "prism/scene/builtin_scenes.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {

SuiteReport run_steadiness_suite(const BenchOptions& o) {
  SuiteReport report{"steadiness"};
  const Scene scene = make_cornell_box();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 256);
  const int per_pass = o.quick ? 2 : 4;
  const int spp = o.spp > 0 ? std::max(o.spp, per_pass) : (o.quick ? 4 : 48);
  Table& t = report.add_table(
      fmt::format("Cornell box {}^2 spectral, {} spp, {} samples per pass", size, spp, per_pass),
      {"regeneration", "passes", "pass s min", "median", "max", "CoV", "samples/s", "steps/pass",
       "live fraction mean", "live fraction p10"});
  nlohmann::json rows = nlohmann::json::array();
  const double slots = static_cast<double>(size) * size;
  for (bool regenerate : {true, false}) {
    RenderSettings settings = cornell_settings(size, spp, TransportKind::spectral, o.threads);
    settings.samples_per_pass = per_pass;
    settings.regenerate_paths = regenerate;
    const RenderResult r = render(scene, settings);
    const RenderMeasurement m = measure(r);
    const auto& s = r.pass_seconds;
    std::vector<double> live;
    std::size_t steps = 0;
    for (const auto& pass : r.pass_live_paths) {
      steps += pass.size();
      for (auto n : pass) live.push_back(static_cast<double>(n) / slots);
    }
    std::vector<double> sorted = live;
    std::sort(sorted.begin(), sorted.end());
    const double p10 = sorted.empty() ? 0.0 : sorted[sorted.size() / 10];
    t.add_row({regenerate ? "on" : "off", static_cast<int>(s.size()), *std::min_element(s.begin(), s.end()),
               median(s), *std::max_element(s.begin(), s.end()), coefficient_of_variation(s), m.samples_per_second,
               s.empty() ? 0.0 : static_cast<double>(steps) / static_cast<double>(s.size()), mean(live), p10});
    rows.push_back({{"regenerate", regenerate},
                    {"pass_seconds", s},
                    {"live_paths_first_pass", r.pass_live_paths.empty() ? std::vector<std::uint32_t>{}
                                                                         : r.pass_live_paths.front()},
                    {"slots", size * size}});
  }
  report.data["rows"] = rows;
  report.notes.push_back("CoV = standard deviation / mean of the pass times; live fraction = live paths per "
                         "wavefront step / pixels, over every step of every pass; each tile runs its own queue, "
                         "so a step's count adds every tile's paths at that step");
  return report;
}

}  // namespace prism::bench
