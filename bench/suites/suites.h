#pragma once
// The `prism bench` suites (issue 8). Each measures one figure family on built-in or
// generated scenes and returns tables; none asserts a speed (targets live in
// BENCHMARKS.md, never in tests). `quick` shrinks every size so the CLI test finishes in
// seconds; `full` selects the long versions (convergence to 1000+ spp, 10M triangles).
#include <functional>
#include <string>
#include <vector>

#include "bench_report.h"

namespace prism::bench {

struct BenchOptions {
  bool quick = false;   // tiny sizes: checks the plumbing, numbers mean nothing
  bool full = false;    // the long versions (minutes to tens of minutes)
  int repeat = 3;       // runs per figure; the median is reported
  int threads = 0;      // 0: all hardware threads
  int spp = 0;          // 0: the suite's default
  int size = 0;         // 0: the suite's default image size (square)
  std::string scene;    // efficiency, convergence: a scene file to render instead of the built-in Cornell box
};

using Suite = std::function<SuiteReport(const BenchOptions&)>;

struct SuiteEntry {
  std::string name;
  std::string description;
  Suite run;
};

const std::vector<SuiteEntry>& all_suites();

SuiteReport run_limit_suite(const BenchOptions& options);
SuiteReport run_throughput_suite(const BenchOptions& options);
SuiteReport run_steadiness_suite(const BenchOptions& options);
SuiteReport run_convergence_suite(const BenchOptions& options);
SuiteReport run_display_suite(const BenchOptions& options);
SuiteReport run_scaling_suite(const BenchOptions& options);
SuiteReport run_startup_suite(const BenchOptions& options);
SuiteReport run_efficiency_suite(const BenchOptions& options);
SuiteReport run_sampler_suite(const BenchOptions& options);
SuiteReport run_denoise_suite(const BenchOptions& options);
SuiteReport run_adaptive_suite(const BenchOptions& options);

}  // namespace prism::bench
