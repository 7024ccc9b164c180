// `npsnet dr-error LOG...` (issue 11): the dead-reckoning error of remote entities, from the
// event logs of two or more nodes of one exercise run with --track-every (track_log.hpp; same
// --dt and --start-at, so their frames are the same scenario ticks).
// Each `track` sample with "source": "remote" (a node's copy of another node's vehicle) is matched
// to the "local" sample of the same id at the same frame in another log (its owner's true
// position); its error is the distance between the two: horizontal (x, y) and 3-D, in metres.
// A remote sample whose owner has no sample at that frame (its node was not running, or its log
// ends earlier) is counted as unmatched. Reported for every observing log, every remote entity
// and all together: count, p50, p90, p99, max (percentiles by nearest rank: the value at rank
// ceil(p n / 100) of the n sorted errors).
// Bad input (a file that cannot be read, a line that is not JSON, a track event with a missing or
// wrong field, one vehicle local in two logs at one frame, a log without track events) is an
// InputError, FILE:LINE: field: message; the command exits 2 and prints no figures.
#pragma once
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace npsnet::node {

struct ErrorStats {
  long count = 0;
  double p50 = 0, p90 = 0, p99 = 0, max = 0;  // m (0 when count is 0)
};
// The statistics of `errors` (any order; sorted in place).
ErrorStats error_stats(std::vector<double>& errors);

struct DrErrorRow {
  std::string name;  // the observing log's file name, the remote entity's id, or "all"
  long unmatched = 0;
  ErrorStats horizontal, full;
};
struct DrErrorReport {
  std::vector<DrErrorRow> per_log, per_entity;  // logs in the order given, entities by id
  DrErrorRow all;
};

// Reads the logs and matches the samples with from_s <= t <= to_s. Throws world::InputError.
DrErrorReport dr_error(const std::vector<std::filesystem::path>& logs, std::optional<double> from_s = {},
                       std::optional<double> to_s = {});
std::string format_report(const DrErrorReport& r);

struct DrErrorOptions {
  std::vector<std::filesystem::path> logs;
  std::optional<double> from_s, to_s;
  CLI::App* command = nullptr;
};
void add_dr_error_command(CLI::App& app, DrErrorOptions& o);
// Runs it when it was the subcommand chosen: 0 ok, 2 bad input (or no sample matched).
std::optional<int> run_dr_error_command(const DrErrorOptions& o);

}  // namespace npsnet::node
