// Helpers of the `npsnet` command line (main.cpp): number checks with readable messages and a
// plain answer to a mistyped subcommand or option.
#pragma once
#include <CLI/CLI.hpp>

#include <string>

namespace npsnet::node {

// A finite number in [lo, hi] (or (lo, hi] when lo_open); rejects nan, inf and text with a
// message that prints the bounds as people write them ("0.01 to 1 s", never 310 digits).
CLI::Validator finite_in(double lo, double hi, const std::string& unit, bool lo_open = false);

// When argv[1] is neither a subcommand of `app` nor a help flag, prints what is wrong (an
// unknown subcommand, or an option given before the subcommand) and returns true.
bool misplaced_first_argument(const CLI::App& app, int argc, char** argv);

// The message for a parse error of `app`: CLI11's, or a plainer one for an unknown argument.
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e);

}  // namespace npsnet::node
