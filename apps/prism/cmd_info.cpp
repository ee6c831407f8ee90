// `prism info [SCENE]`: version, build configuration, library versions and the built-in
// scenes; with a scene name or file, the summary of that scene as loaded.
#include <iostream>
#include <memory>

#include <embree3/rtcore.h>
#include <oneapi/tbb/version.h>

#include "command.h"
#include "prism/core/parallel.h"
#include "prism/core/version.h"
#include "prism/scene/load_scene.h"
#include "prism/scene/scene_summary.h"

namespace prism::cli {

void add_info_command(CLI::App& root, Action& action) {
  CLI::App* cmd = root.add_subcommand(
      "info", "Print version, build and library information and the built-in scenes, or a scene's summary");
  struct InfoOptions {
    std::string scene;
    bool allow_external_paths = false;
    std::string material_variant;
  };
  auto options = std::make_shared<InfoOptions>();
  cmd->add_option("scene", options->scene, "Built-in scene name or scene file to summarise");
  cmd->add_flag("--allow-external-paths", options->allow_external_paths,
                "Let the scene file refer to files outside its own folder");
  cmd->add_option("--variant", options->material_variant,
                  "Summarise the scene wearing this material variant (glTF KHR_materials_variants)");
  cmd->callback([options, &action] {
    action = [options] {
      if (!options->scene.empty()) {
        const Scene scene =
            load_scene(options->scene, LoadOptions{.allow_external_paths = options->allow_external_paths,
                                                   .material_variant = options->material_variant});
        std::cout << format_scene_summary(scene);
        return 0;
      }
      std::cout << "prism " << kVersion << " (" << kBuildType << " build)\n"
                << "embree " << RTC_VERSION_STRING << '\n'
                << "onetbb " << TBB_runtime_version() << " (built against " << TBB_VERSION_STRING << ")\n"
                << "hardware threads " << ThreadLimit::hardware_threads() << '\n'
                << "built-in scenes:";
      for (const auto& name : all_builtin_scene_names()) std::cout << ' ' << name;
      std::cout << '\n';
      return 0;
    };
  });
}

}  // namespace prism::cli
