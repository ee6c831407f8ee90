// `prism bench SUITE --quick --json FILE` for every suite: the JSON document is
// well-formed — machine facts, one entry per suite, every table's rows as long as its
// column list, cells strings, finite numbers or null. No timing is asserted (issue 8:
// speed targets live in BENCHMARKS.md, never in tests).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

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

INSTANTIATE_TEST_SUITE_P(Suites, BenchCli,
                         ::testing::Values("limit", "throughput", "steadiness", "convergence", "efficiency",
                                           "display", "scaling", "startup"));

}  // namespace
}  // namespace prism
