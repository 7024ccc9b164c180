// The command line of the benchmarks that have only --quick and --csv (bench_aoi,
// bench_record_replay), parsed by CLI11 as the node's own (src/node/cli.cpp).
#pragma once
#include <CLI/CLI.hpp>

#include <cstdlib>
#include <string>

namespace npsnet::bench {

struct BenchArgs {
  bool quick = false;  // fewer sizes, shorter runs, no CSV
  std::string csv;     // where the CSV goes ("" = none)
};

// `csv` is the default CSV path. Prints the usage and exits (0 for --help, 2 for bad arguments).
inline BenchArgs bench_args(int argc, char** argv, const std::string& description, const std::string& quick_help,
                            std::string csv) {
  BenchArgs a;
  a.csv = std::move(csv);
  CLI::App app{description};
  app.add_flag("--quick", a.quick, quick_help);
  app.add_option("--csv", a.csv, "write the CSV here")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e) == 0 ? 0 : 2);
  }
  return a;
}

}  // namespace npsnet::bench
