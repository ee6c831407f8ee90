#pragma once
// Each subcommand lives in its own file and registers itself on the root CLI11 app.
// The registration stores the action to run after a successful parse in `action`.
#include <functional>

#include <CLI/CLI.hpp>

namespace prism::cli {

using Action = std::function<int()>;

void add_render_command(CLI::App& root, Action& action);
void add_info_command(CLI::App& root, Action& action);
void add_merge_command(CLI::App& root, Action& action);
void add_color_command(CLI::App& root, Action& action);
void add_tonemap_command(CLI::App& root, Action& action);
void add_view_command(CLI::App& root, Action& action);
void add_bench_command(CLI::App& root, Action& action);
void add_generate_command(CLI::App& root, Action& action);
void add_denoise_command(CLI::App& root, Action& action);

}  // namespace prism::cli
