// The `prism` command line: subcommands are thin adapters over the library.
// Exit status: 0 success, 1 runtime error, 2 usage error. Errors are one line on stderr.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "command_line.h"
#include "prism/core/error.h"
#include "prism/core/printable_text.h"
#include "prism/core/version.h"

namespace {

// Messages may quote the input (a file name, a scene's text, bytes of a binary file):
// printed through printable_text, so that they stay one line of text on any terminal.
int report_error(const std::string& what, int exit_code) {
  std::cerr << "prism: error: " << prism::printable_text(what) << '\n';
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Prism: a spectral, colour-managed path tracer", "prism"};
  app.set_version_flag("--version", std::string("prism ") + prism::kVersion);
  app.require_subcommand(0, 1);

  prism::cli::Action action;
  prism::cli::add_render_command(app, action);
  prism::cli::add_info_command(app, action);
  prism::cli::add_merge_command(app, action);
  prism::cli::add_color_command(app, action);
  prism::cli::add_tonemap_command(app, action);
  prism::cli::add_view_command(app, action);
  prism::cli::add_bench_command(app, action);
  prism::cli::add_generate_command(app, action);
  prism::cli::add_denoise_command(app, action);

  if (argc <= 1) {  // `prism` alone asks what it does: it must not start rendering
    std::cout << app.help();
    return 0;
  }
  try {
    prism::cli::parse_command_line(app, std::vector<std::string>(argv + 1, argv + argc));
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return report_error(e.what(), 2);
  }

  try {
    if (!action) return report_error("no subcommand given (see prism --help)", 2);
    return action();
  } catch (const prism::UsageError& e) {
    return report_error(e.what(), 2);
  } catch (const CLI::ParseError& e) {
    return report_error(e.what(), 2);
  } catch (const std::exception& e) {
    return report_error(e.what(), 1);
  }
}
