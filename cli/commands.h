#pragma once

#include <CLI/CLI.hpp>

/// Each subcommand registers itself on the root app. A subcommand's callback throws
/// cavity::core::Error (or CLI11's errors) on failure; main turns those into a message and an exit
/// status (exit_codes.h).
namespace cavity::cli {

void add_sign_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_triangulate_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_cdt_command(CLI::App& app);
void add_jtets_command(CLI::App& app);
void add_experiment_command(CLI::App& app);

}  // namespace cavity::cli
