#include "node/usr1_signal.hpp"

#include <csignal>

namespace npsnet::node {

namespace {
volatile std::sig_atomic_t g_usr1 = 0;
extern "C" void on_usr1(int) { g_usr1 = 1; }
}  // namespace

Usr1Signal::Usr1Signal() {
  struct sigaction sa {};
  sa.sa_handler = on_usr1;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGUSR1, &sa, nullptr);
}

Usr1Signal::~Usr1Signal() { std::signal(SIGUSR1, SIG_DFL); }

bool Usr1Signal::take() {
  if (!g_usr1) return false;
  g_usr1 = 0;
  return true;
}

}  // namespace npsnet::node
