#include "node/cli.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace npsnet::node {

namespace {
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

std::string names_of(const CLI::App& app) {
  std::string s;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    s += (s.empty() ? "" : ", ") + sub->get_name();
  return s;
}
}  // namespace

CLI::Validator finite_in(double lo, double hi, const std::string& unit, bool lo_open) {
  const std::string range = (lo_open ? "more than " + num(lo) + " up to " : num(lo) + " to ") + num(hi) +
                            (unit.empty() ? "" : " " + unit);
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || end == s.c_str() || *end != '\0') return "'" + s + "' is not a number";
        if (!std::isfinite(v)) return "'" + s + "' is not a finite number; give " + range;
        if (v < lo || v > hi || (lo_open && v <= lo)) return "must be " + range + " (got " + num(v) + ")";
        return "";
      },
      "NUMBER in " + range);
}

bool misplaced_first_argument(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return false;  // CLI11 says that a subcommand is required
  std::string a = argv[1];
  if (a == "-h" || a == "--help" || a == "--help-all") return false;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->check_name(a)) return false;
  if (a.size() > 1 && a[0] == '-') {
    const std::string opt = a.substr(0, a.find('='));
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_option_no_throw(opt)) {
        std::fprintf(stderr, "npsnet: %s is an option of '%s': it goes after the subcommand, e.g. npsnet %s %s ...\n",
                     opt.c_str(), sub->get_name().c_str(), sub->get_name().c_str(), opt.c_str());
        return true;
      }
    std::fprintf(stderr, "npsnet: unknown option '%s'; give a subcommand first (%s); npsnet --help shows examples\n",
                 opt.c_str(), names_of(app).c_str());
    return true;
  }
  std::fprintf(stderr, "npsnet: unknown subcommand '%s' (known: %s); npsnet --help shows examples\n", a.c_str(),
               names_of(app).c_str());
  return true;
}

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e) {
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    std::string where = "npsnet";
    for (const CLI::App* sub : app.get_subcommands()) where += " " + sub->get_name();
    std::string what = e.what();
    const auto colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    return where + ": unknown option or extra argument: " + what + " (" + where + " --help lists the options)";
  }
  if (e.get_name() == "RequiredError" && app.get_subcommands().empty())
    return std::string("npsnet: give a subcommand (") + names_of(app) + "); npsnet --help shows examples";
  return std::string("npsnet: ") + e.what();
}

}  // namespace npsnet::node
