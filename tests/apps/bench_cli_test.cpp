// `prism bench SUITE --quick --json FILE` for every suite: the JSON document is
// well-formed — machine facts, one entry per suite, every table's rows as long as its
// column list, cells strings, finite numbers or null. No timing is asserted (issue 8:
// speed targets live in BENCHMARKS.md, never in tests).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace prism {
namespace {
namespace fs = std::filesystem;

class BenchCli : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("prism-bench-test-" + std::to_string(::getpid()) + "-" + GetParam());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_P(BenchCli, QuickRunWritesWellFormedJson) {
  const fs::path json_path = dir_ / "bench.json";
  const std::string cmd = std::string(PRISM_CLI) + " bench " + GetParam() + " --quick --threads 2 --json " +
                          json_path.string() + " >" + (dir_ / "log").string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream log_file(dir_ / "log");
  const std::string log(std::istreambuf_iterator<char>(log_file), {});
  if (log.find("without the bench suites") != std::string::npos) GTEST_SKIP() << "built without bench/";
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd << '\n' << log;
  std::ifstream in(json_path);
  const nlohmann::json doc = nlohmann::json::parse(in);  // throws (fails the test) when malformed
  EXPECT_GE(doc["machine"]["hardware_threads"].get<int>(), 1);
  EXPECT_TRUE(doc["machine"]["cpu_model"].is_string());
  EXPECT_TRUE(doc["machine"]["load_average_1min"].is_number());
  ASSERT_EQ(doc["suites"].size(), 1u);
  const auto& suite = doc["suites"][0];
  EXPECT_EQ(suite["suite"], GetParam());
  ASSERT_FALSE(suite["tables"].empty());
  for (const auto& table : suite["tables"]) {
    EXPECT_TRUE(table["title"].is_string());
    ASSERT_FALSE(table["rows"].empty()) << table["title"];
    for (const auto& row : table["rows"]) {
      ASSERT_EQ(row.size(), table["columns"].size()) << table["title"];
      for (const auto& cell : row) EXPECT_TRUE(cell.is_string() || cell.is_number() || cell.is_null()) << cell;
    }
  }
  EXPECT_TRUE(suite["data"].is_object());
}

// limit --repeat N: N rounds, each with its own raw rates and renders; the efficiency is
// the median of the rounds' ratios (each a ratio of figures taken moments apart).
TEST(BenchLimit, RepeatRunsRoundsAndReportsTheMedianOfTheirRatios) {
  const fs::path dir = fs::temp_directory_path() / ("prism-bench-limit-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path json_path = dir / "limit.json";
  const std::string cmd = std::string(PRISM_CLI) + " bench limit --quick --repeat 3 --threads 1 --json " +
                          json_path.string() + " >" + (dir / "log").string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream log_file(dir / "log");
  const std::string log(std::istreambuf_iterator<char>(log_file), {});
  if (log.find("without the bench suites") != std::string::npos) {
    fs::remove_all(dir);
    GTEST_SKIP() << "built without bench/";
  }
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd << '\n' << log;
  std::ifstream in(json_path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  fs::remove_all(dir);
  const auto& rows = doc["suites"][0]["data"]["rows"];
  ASSERT_EQ(rows.size(), 2u);  // spectral and RGB, one thread
  for (const auto& row : rows) {
    EXPECT_EQ(row["rounds"], 3);
    const auto& per_round = row["efficiency_vs_closest_per_round"];
    ASSERT_EQ(per_round.size(), 3u) << row["mode"];
    ASSERT_EQ(row["renderer_rays_per_s_per_round"].size(), 3u) << row["mode"];
    std::vector<double> sorted = per_round.get<std::vector<double>>();
    std::sort(sorted.begin(), sorted.end());
    EXPECT_DOUBLE_EQ(row["efficiency_vs_closest"].get<double>(), sorted[1]) << row["mode"];
  }
}

INSTANTIATE_TEST_SUITE_P(Suites, BenchCli,
                         ::testing::Values("limit", "throughput", "steadiness", "convergence", "efficiency",
                                           "display", "scaling", "startup"));

}  // namespace
}  // namespace prism
