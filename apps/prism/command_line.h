#pragma once
// Parsing of the command line with POSIX's end-of-options delimiter.
//
// POSIX (XBD 12.2, utility syntax guideline 10): the first `--` argument ends the options;
// every argument after it is an operand, even one that begins with '-' (how a negative
// number or a file named "-x.exr" is passed). CLI11 2.1 honours `--` inside a subcommand
// only while that subcommand still lacks the minimum count of its positional arguments;
// otherwise (no positionals, or their minimum already met) it ends the subcommand there
// and hands the arguments after `--` to the parent command, which rejects them as "not
// expected" or, worse, reads them as its own options. parse_command_line therefore never
// shows CLI11 the operands after `--`: it shows it a placeholder for each, which CLI11
// assigns to positional arguments as it assigns any positional word, then puts the
// operands in their places and converts and checks the values.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace prism::cli {

// Parses `args` (without the program name) into `app`, as CLI::App::parse does, with `--`
// handled as above. Throws what CLI::App::parse throws (CLI::ParseError: operands no
// positional argument takes, too few or too many for one), its messages naming the operands.
void parse_command_line(CLI::App& app, const std::vector<std::string>& args);

}  // namespace prism::cli
