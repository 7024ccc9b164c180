// Runs the built `npsnet` binary with arguments (a shell command line) and returns its exit code
// and its stdout + stderr. Header-only, for the tests of the command-line contract.
#pragma once
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "support/dirs.hpp"

namespace npsnet::test {

struct CliOut {
  int rc = -1;  // exit code, or -1 when killed by a signal
  std::string text;
};

inline CliOut npsnet_cli(const std::string& args) {
  const std::string cmd = std::string(npsnet::dirs::binary()) + "/npsnet " + args + " 2>&1";
  CliOut o;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return o;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) o.text.append(buf, n);
  const int st = pclose(p);
  o.rc = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return o;
}

}  // namespace npsnet::test
