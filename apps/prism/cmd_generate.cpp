// `prism generate atrium --triangles N -o FILE.(json|pbrt|glb)`: writes a generated test scene
// (see src/prism/scene/loaders/atrium_generator.h) in Prism's JSON, the pbrt-v4 format or binary glTF,
// chosen by the output's extension.
#include <algorithm>
#include <cctype>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "command.h"
#include "prism/core/error.h"
#include "prism/scene/loaders/atrium_generator.h"
#include "prism/scene/loaders/gltf_writer.h"
#include "prism/scene/loaders/scene_writers.h"
#include "prism/scene/scene_summary.h"

namespace prism::cli {

void add_generate_command(CLI::App& root, Action& action) {
  CLI::App* cmd = root.add_subcommand("generate", "Write a generated test scene (atrium) as .json, .pbrt or .glb");
  struct GenerateOptions {
    std::string kind;
    std::size_t triangles = 1'000'000;
    std::string output;
  };
  auto options = std::make_shared<GenerateOptions>();
  cmd->add_option("kind", options->kind, "What to generate: atrium")->required()->check(CLI::IsMember({"atrium"}));
  cmd->add_option("--triangles", options->triangles, "Approximate triangle count (10000 to 200000000)")
      ->capture_default_str();
  cmd->add_option("-o,--output", options->output, "Output file: .json (prism-scene/1), .pbrt (pbrt-v4) or .glb (glTF 2.0)")->required();
  cmd->callback([options, &action] {
    action = [options] {
      std::string extension = std::filesystem::path(options->output).extension().string();
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (extension != ".json" && extension != ".pbrt" && extension != ".glb")
        throw UsageError(fmt::format("generate: cannot write '{}' files (use .json, .pbrt or .glb)", extension));
      const Scene scene = loaders::generate_atrium(options->triangles);
      if (extension == ".json") loaders::write_scene_json(scene, options->output);
      else if (extension == ".pbrt") loaders::write_scene_pbrt(scene, options->output);
      else loaders::write_scene_glb(scene, options->output);
      std::cout << fmt::format("prism: generated {} with {} triangles -> {}\n", scene.name, scene.triangle_count(),
                               options->output);
      return 0;
    };
  });
}

}  // namespace prism::cli
