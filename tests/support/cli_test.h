#pragma once
// A gtest fixture for end-to-end tests of the `prism` binary (PRISM_CLI, defined for
// prism_tests): a scratch folder per test, run(args) with stdout and stderr captured to a
// log, and the log's text for failure messages.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/scratch_folder.h"

namespace prism::test {

class CliTest : public ::testing::Test {
 protected:
  // Exit status of `prism ARGS` (-1 when it did not exit normally).
  int run(const std::string& args) {
    const std::string cmd = std::string(PRISM_CLI) + " " + args + " >" + (dir_ / "log").string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string log() const {
    std::ifstream in(dir_ / "log");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  const ScratchFolder scratch_;
  const std::filesystem::path dir_ = scratch_.path();
};

}  // namespace prism::test
