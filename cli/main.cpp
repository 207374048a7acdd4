#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "cavity/core/base/error.h"
#include "cavity/core/version.h"
#include "cavity/predicates/fp_environment.h"
#include "commands.h"
#include "exit_codes.h"

// CLI11's set-up below the environment check throws only for a programming error (two options
// of one name), which every CLI test would catch; everything that runs is inside the try.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    // The predicates are proved for round-to-nearest without flush-to-zero; refuse to run in any
    // other floating-point environment rather than print wrong signs.
    if (!cavity::predicates::fp_environment_is_exact()) {
        std::fprintf(stderr,
                     "cavity: the floating-point environment is not round-to-nearest double "
                     "without flush-to-zero; exact predicates cannot run\n");
        return 2;
    }
    CLI::App app{"cavity: exact, instrumented 3D Delaunay triangulation"};
    app.require_subcommand(1);
    cavity::cli::add_sign_command(app);
    cavity::cli::add_generate_command(app);
    cavity::cli::add_triangulate_command(app);
    cavity::cli::add_check_command(app);
    cavity::cli::add_cdt_command(app);
    cavity::cli::add_jtets_command(app);
    cavity::cli::add_experiment_command(app);
    const std::string version = std::string("cavity ") + cavity::core::kVersion;
    app.set_version_flag("--version", version);
    for (CLI::App* command : app.get_subcommands({})) {
        command->set_version_flag("--version", version);
        // After the command's own footer (generate lists its distributions there).
        const std::string own = command->get_footer();
        command->footer(own.empty() ? std::string(cavity::cli::kExitStatusHelp)
                                    : own + "\n" + cavity::cli::kExitStatusHelp);
    }
    app.footer(cavity::cli::kExitStatusHelp);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            return app.exit(e);  // --help, --version: printed to stdout, success
        }
        std::fprintf(stderr,
                     "cavity: %s\nRun with --help for the usage.\n",
                     cavity::cli::usage_message(e.what()).c_str());
        return cavity::cli::kExitUsage;
    } catch (const cavity::core::Error& e) {
        std::fprintf(stderr, "cavity: %s\n", e.what());
        return cavity::cli::exit_code(e.kind());
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "cavity: out of memory\n");
        return cavity::cli::kExitSystem;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cavity: internal error: %s\n", e.what());
        return cavity::cli::kExitInternal;
    }
    return 0;
}
