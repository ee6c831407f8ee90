// `prism info`: version, build configuration, library versions and the built-in scenes.
#include <iostream>

#include <embree3/rtcore.h>
#include <oneapi/tbb/version.h>

#include "command.h"
#include "prism/core/parallel.h"
#include "prism/core/version.h"
#include "prism/scene/builtin_scenes.h"

namespace prism::cli {

void add_info_command(CLI::App& root, Action& action) {
  CLI::App* cmd = root.add_subcommand("info", "Print version, build and library information and the built-in scenes");
  cmd->callback([&action] {
    action = [] {
      std::cout << "prism " << kVersion << " (" << kBuildType << " build)\n"
                << "embree " << RTC_VERSION_STRING << '\n'
                << "onetbb " << TBB_runtime_version() << " (built against " << TBB_VERSION_STRING << ")\n"
                << "hardware threads " << ThreadLimit::hardware_threads() << '\n'
                << "built-in scenes:";
      for (const auto& name : builtin_scene_names()) std::cout << ' ' << name;
      std::cout << '\n';
      return 0;
    };
  });
}

}  // namespace prism::cli
