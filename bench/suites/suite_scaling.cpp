// scaling: samples/s with 1, 2, … threads up to the hardware's, parallel efficiency
// = speedup / threads. Median of --repeat runs per thread count.
#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "prism/core/parallel.h"
#include "prism/scene/builtin_scenes.h"
#include "render_measure.h"
#include "suites.h"

namespace prism::bench {

SuiteReport run_scaling_suite(const BenchOptions& o) {
  SuiteReport report{"scaling"};
  const Scene scene = make_cornell_box();
  const int size = o.size > 0 ? o.size : (o.quick ? 16 : 256);
  const int spp = o.spp > 0 ? o.spp : (o.quick ? 1 : 16);
  const int repeat = o.quick ? 1 : std::max(1, o.repeat);
  const int hardware = o.threads > 0 ? o.threads : ThreadLimit::hardware_threads();
  std::vector<int> counts{1};
  for (int n = 2; n <= hardware; n *= 2) counts.push_back(n);
  if (counts.back() != hardware) counts.push_back(hardware);

  Table& t = report.add_table(fmt::format("Cornell box {}^2 spectral, {} spp, median of {} runs", size, spp, repeat),
                              {"threads", "samples/s", "speedup", "parallel efficiency"});
  double single = 0.0;
  nlohmann::json rows = nlohmann::json::array();
  for (int threads : counts) {
    const RenderSettings settings = cornell_settings(size, spp, TransportKind::spectral, threads);
    std::vector<double> sps;
    for (int i = 0; i < repeat; ++i) sps.push_back(measure(render(scene, settings)).samples_per_second);
    const double med = median(sps);
    if (threads == 1) single = med;
    const double speedup = single > 0 ? med / single : 0.0;
    t.add_row({threads, med, speedup, speedup / threads});
    rows.push_back({{"threads", threads}, {"samples_per_s", sps}});
  }
  report.data["rows"] = rows;
  report.notes.push_back("on a shared machine the all-threads figure competes with other processes: read the "
                         "efficiency with the load average beside it");
  return report;
}

}  // namespace prism::bench
