#pragma once
// `prism color`: queries of the colour library. This file owns the `color` subcommand
// itself; other files add sub-subcommands to it.
//
// To add sub-subcommands from another file (e.g. cmd_color_spectrum.cpp):
//   void add_color_spectrum_commands(CLI::App& color, Action& action) {
//     CLI::App* sub = color.add_subcommand("spectrum", "...");
//     sub->callback([&action, ...] { action = [...] { ...; return 0; }; });
//   }
// and register it in main.cpp after add_color_command(app, action):
//   prism::cli::add_color_spectrum_commands(*prism::cli::color_command(app), action);
// color_command() creates the `color` subcommand when it does not exist yet, so the two
// registrations work in either order.
#include <string>

#include <CLI/CLI.hpp>

#include "command.h"

namespace prism::cli {

// The `color` subcommand of root, created on first use (without sub-subcommands).
CLI::App* color_command(CLI::App& root);

// Defined in cmd_color_spectrum.cpp (the spectral half of issue 3).
void add_color_spectrum_commands(CLI::App& color, Action& action);

// Parses a whole string as one finite number; anything else is a UsageError naming `what`.
double parse_number(const std::string& text, const std::string& what);

}  // namespace prism::cli
