#pragma once
// `--environment`, `--environment-nits`, `--environment-rotation` for `prism render` and
// `prism view` (scene/environment_override.h).
#include <CLI/CLI.hpp>

#include "prism/scene/environment_override.h"

namespace prism::cli {

void add_environment_options(CLI::App* command, EnvironmentOverride& environment);

}  // namespace prism::cli
