// A small pool of worker threads for the data-parallel stages of one node tick (issue 13):
// dynamics per vehicle, collision broad phase per bucket range, narrow phase per entity / pair.
//
// Contract:
//  * Jobs(n): n threads in all, the calling thread included (n - 1 workers are started; n = 1
//    starts none and runs everything on the caller, the single-threaded path).
//  * for_chunks(count, grain, fn[, per_thread]): splits [0, count) into k = chunks(count, grain,
//    per_thread) contiguous ranges (k at most kMaxChunks), chunk c = [count * c / k, count *
//    (c + 1) / k), and calls fn(c, begin, end) once for each, returning when all are done.
//    Chunks are claimed, not assigned: the caller starts on them at once and a worker takes the
//    next unclaimed one when it arrives, so a stage never waits for a worker to wake (a short
//    stage may run wholly on the caller). The caller claims from the first chunk up, workers
//    from the last down: from stage to stage and tick to tick the same items tend to stay on the
//    same thread, and their data in that core's cache. Which thread runs a chunk changes
//    nothing: fn's outputs are keyed by the chunk index c. The split depends only on count, grain, per_thread
//    and threads(): a stage whose chunks write only their own outputs (per-chunk buffers, or the
//    slots of their own range), merged afterwards in chunk order, gives the same bytes as one
//    thread walking [0, count) in order.
//  * An exception thrown by fn is rethrown on the caller once every chunk has ended (the one of
//    the lowest chunk when several threw), so an error names the first bad item in index order.
//  * Not reentrant: for_chunks is called from one thread (the tick's), never from inside fn.
//    No allocation per call. A worker spins for kSpinUs after a job for the next one (a tick's
//    stages follow each other within microseconds; waking a sleeping thread costs 10-50 us),
//    then sleeps on a condition variable. wake() lets workers start spinning ahead of a burst of
//    stages (the start of a tick).
#pragma once
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace npsnet::core {

class Jobs {
 public:
  // The default thread count: std::thread::hardware_concurrency(), at least 1, at most kDefaultCap.
  static int default_threads();
  static constexpr int kDefaultCap = 8, kMaxThreads = 64;
  static constexpr int kMaxPerThread = 8, kMaxChunks = kMaxThreads * kMaxPerThread;  // chunks(): per_thread

  explicit Jobs(int threads = 1);  // threads clamped to [1, kMaxThreads]
  ~Jobs();
  Jobs(const Jobs&) = delete;
  Jobs& operator=(const Jobs&) = delete;

  int threads() const { return threads_; }
  // Caps every stage's grain (0 = no cap): tests set 1 so that every stage splits as finely as
  // the thread count allows, whatever its size.
  void set_max_grain(size_t g) { max_grain_ = g; }
  // How many chunks for_chunks splits `count` items into: min(threads * per_thread, count /
  // grain), >= 1. per_thread (1 to kMaxPerThread) > 1 for the long stages of many alike items:
  // a thread that finishes early (or the caller, while a worker is late) claims more of them
  // instead of waiting at the stage's end.
  int chunks(size_t count, size_t grain, int per_thread = 1) const {
    size_t g = grain ? grain : 1;
    if (max_grain_ && g > max_grain_) g = max_grain_;
    const size_t k = count / g, most = static_cast<size_t>(threads_) * std::clamp(per_thread, 1, kMaxPerThread);
    return k < 1 ? 1 : k > most ? static_cast<int>(most) : static_cast<int>(k);
  }
  static size_t chunk_begin(size_t count, int c, int k) { return count * static_cast<size_t>(c) / static_cast<size_t>(k); }

  template <class F>
  void for_chunks(size_t count, size_t grain, F&& fn, int per_thread = 1) {
    const int k = chunks(count, grain, per_thread);
    if (k == 1) {
      fn(0, size_t{0}, count);
      return;
    }
    run(count, k, &call<std::remove_reference_t<F>>, &fn);
  }

  // Workers that sleep wake and spin (for kSpinUs) waiting for the next for_chunks.
  void wake();
  static constexpr int kSpinUs = 250;
  // A caller that knows when its next burst of stages comes (a paced node, its tick's deadline)
  // calls wake() this long before it, off the burst's clock: the workers are spinning when it
  // starts (kPrewakeUs + the sleep's overshoot, ~60 us here, stays under kSpinUs).
  static constexpr int kPrewakeUs = 120;

 private:
  using Call = void (*)(void* ctx, int chunk, size_t begin, size_t end);
  template <class F>
  static void call(void* ctx, int c, size_t b, size_t e) {
    (*static_cast<F*>(ctx))(c, b, e);
  }
  void run(size_t count, int k, Call fn, void* ctx);
  void work();
  void claim_chunks(uint32_t generation, bool from_back);
  // state_: generation (32 bits) | end of the unclaimed chunks (16) | their start (16): the caller
  // claims the start, workers the one before the end. A claim is one compare-exchange; when
  // start meets end every chunk is taken and the claimer's part is over.
  static uint32_t generation_of(uint64_t s) { return static_cast<uint32_t>(s >> 32); }

  int threads_ = 1;
  size_t max_grain_ = 0;
  std::vector<std::thread> workers_;
  // The job being run: written by the caller before the generation changes, read by a thread
  // only after it claimed one of its chunks (the job cannot end before that chunk does).
  Call fn_ = nullptr;
  void* ctx_ = nullptr;
  size_t count_ = 0;
  int k_ = 0;
  std::atomic<uint64_t> state_{0};
  std::atomic<int> finished_{0};  // chunks of the current job done
  std::atomic<int> sleepers_{0};  // workers waiting on wake_
  std::atomic<bool> stop_{false};
  std::atomic<uint32_t> wakes_{0};  // wake() calls: a sleeping worker wakes and spins again
  std::mutex mu_;
  std::condition_variable wake_;
  std::vector<std::exception_ptr> errors_;  // per chunk
};

// fn(chunk, begin, end) over [0, count): on `jobs` in its chunks(count, grain, per_thread)
// ranges, or once on the calling thread when there is no pool. Returns how many ranges ran.
template <class F>
int run_chunks(Jobs* jobs, size_t count, size_t grain, F&& fn, int per_thread = 1) {
  if (!jobs) {
    fn(0, size_t{0}, count);
    return 1;
  }
  const int k = jobs->chunks(count, grain, per_thread);
  jobs->for_chunks(count, grain, fn, per_thread);
  return k;
}

}  // namespace npsnet::core
