// `prism view` in a prism built without the viewer (-DPRISM_VIEWER=OFF, e.g. for render
// farm nodes, which have no GLFW, OpenGL or Dear ImGui): the subcommand exists, takes what
// it is given, and says why it cannot run (exit 1).
#include "command.h"
#include "prism/core/error.h"

namespace prism::cli {

void add_view_command(CLI::App& root, Action& action) {
  CLI::App* cmd = root.add_subcommand("view", "Open a scene in the interactive viewer (not in this build)");
  cmd->allow_extras();
  cmd->callback([&action] {
    action = []() -> int {
      throw Error("this prism was built without the viewer (configure with -DPRISM_VIEWER=ON); use prism render");
    };
  });
}

}  // namespace prism::cli
