// `prism bench SUITE... [--json FILE] [--quick|--full] [--repeat N] [--threads N]`: the
// performance instruments of issue 8. The suites live in bench/suites/ (a library linked
// in by bench/CMakeLists.txt); this file only parses options, runs them and writes the
// table and JSON. See BENCHMARKS.md for what each suite measures and the figures.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "prism/core/error.h"

#if PRISM_HAVE_BENCH_SUITES
#include "suites.h"
#endif

namespace prism::cli {

#if PRISM_HAVE_BENCH_SUITES
namespace {

struct BenchCommandOptions {
  std::vector<std::string> suites;
  std::string json_path;
  bool list = false;
  bench::BenchOptions run;
};

std::vector<const bench::SuiteEntry*> selected_suites(const std::vector<std::string>& names) {
  std::vector<const bench::SuiteEntry*> out;
  for (const auto& name : names) {
    bool found = false;
    for (const auto& s : bench::all_suites()) {
      if (name == "all" || name == s.name) {
        out.push_back(&s);
        found = true;
      }
    }
    if (!found) {
      std::string known;
      for (const auto& s : bench::all_suites()) known += " " + s.name;
      throw UsageError("unknown bench suite '" + name + "' (known:" + known + ", all)");
    }
  }
  return out;
}

int run_bench(const BenchCommandOptions& o) {
  if (o.list) {
    for (const auto& s : bench::all_suites()) std::cout << s.name << "  " << s.description << '\n';
    return 0;
  }
  if (o.suites.empty()) throw UsageError("bench: name a suite (or `all`); --list shows them");
  if (o.run.quick && o.run.full) throw UsageError("bench: --quick and --full exclude each other");
  const auto suites = selected_suites(o.suites);
  std::ofstream json_file;
  if (!o.json_path.empty()) {
    json_file.open(o.json_path);
    if (!json_file) throw Error("cannot write " + o.json_path);
  }
  nlohmann::json doc{{"machine", bench::machine_json()},
                     {"options",
                      {{"quick", o.run.quick}, {"full", o.run.full}, {"repeat", o.run.repeat},
                       {"threads", o.run.threads}, {"spp", o.run.spp}, {"size", o.run.size},
                       {"scene", o.run.scene}}},
                     {"suites", nlohmann::json::array()}};
  std::cout << "load average (1 min) at start: " << bench::load_average_1min() << "\n\n";
  for (const auto* suite : suites) {
    const double load = bench::load_average_1min();
    bench::SuiteReport report = suite->run(o.run);
    std::cout << bench::format_report(report) << '\n' << std::flush;
    nlohmann::json j = bench::report_json(report);
    j["load_average_1min_before"] = load;
    j["load_average_1min_after"] = bench::load_average_1min();
    doc["suites"].push_back(std::move(j));
  }
  if (json_file.is_open()) json_file << doc.dump(2) << '\n';
  return 0;
}

}  // namespace
#endif

void add_bench_command(CLI::App& root, Action& action) {
  CLI::App* cmd = root.add_subcommand("bench", "Run performance benchmark suites and print their figures");
#if PRISM_HAVE_BENCH_SUITES
  auto o = std::make_shared<BenchCommandOptions>();
  std::string names;
  for (const auto& s : bench::all_suites()) names += (names.empty() ? "" : ", ") + s.name;
  cmd->add_option("suites", o->suites, "Suites to run: " + names + ", or all");
  cmd->add_option("--json", o->json_path, "Also write the figures as JSON to this file");
  cmd->add_flag("--list", o->list, "List the suites and exit");
  cmd->add_flag("--quick", o->run.quick, "Tiny sizes: checks the plumbing in seconds; figures mean nothing");
  cmd->add_flag("--full", o->run.full, "The long versions (convergence to 2048 spp, 10M triangles, ...)");
  cmd->add_option("--repeat", o->run.repeat, "Runs per figure; the median is reported")->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o->run.threads, "Worker threads (0: all)")->check(CLI::Range(0, 4096));
  cmd->add_option("--spp", o->run.spp, "Samples per pixel (0: each suite's default)")->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--size", o->run.size, "Square image size (0: each suite's default)")->check(CLI::Range(0, 16384));
  cmd->add_option("--scene", o->run.scene,
                  "efficiency, convergence: render this scene file (e.g. data/scenes/cornell-box.pbrt, through "
                  "its loader) instead of the built-in Cornell box");
  cmd->callback([o, &action] { action = [o] { return run_bench(*o); }; });
#else
  cmd->allow_extras();
  cmd->callback([&action] {
    action = [] {
      throw Error("this prism was built without the bench suites (configure with PRISM_BUILD_BENCHMARKS=ON)");
      return 1;
    };
  });
#endif
}

}  // namespace prism::cli
