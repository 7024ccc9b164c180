// SIGUSR1 asks a running node for its summary (counters, remote entities). The handler only sets
// a flag; the tick loop takes it (take()) and prints outside the signal context.
// One instance at a time installs the handler; its destructor restores the default action.
#pragma once

namespace npsnet::node {

class Usr1Signal {
 public:
  Usr1Signal();
  ~Usr1Signal();
  Usr1Signal(const Usr1Signal&) = delete;
  Usr1Signal& operator=(const Usr1Signal&) = delete;
  // True once for each SIGUSR1 received since the last call (several arrivals count once).
  bool take();
};

}  // namespace npsnet::node
