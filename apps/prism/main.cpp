// The `prism` command line: subcommands are thin adapters over the library.
// Exit status: 0 success, 1 runtime error, 2 usage error. Errors are one line on stderr.
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "command.h"
#include "prism/core/error.h"
#include "prism/core/version.h"

namespace {

int report_error(const std::string& what, int exit_code) {
  std::cerr << "prism: error: " << what << '\n';
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Prism: a spectral, colour-managed path tracer"};
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

  try {
    app.parse(argc, argv);
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
    if (!action) {
      // No subcommand: render the default scene, as `prism render` would.
      CLI::App fallback{"prism"};
      prism::cli::Action render_action;
      prism::cli::add_render_command(fallback, render_action);
      fallback.parse(std::vector<std::string>{"render"});
      return render_action();
    }
    return action();
  } catch (const prism::UsageError& e) {
    return report_error(e.what(), 2);
  } catch (const CLI::ParseError& e) {
    return report_error(e.what(), 2);
  } catch (const std::exception& e) {
    return report_error(e.what(), 1);
  }
}
