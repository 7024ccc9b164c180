// A small pool of worker threads for the data-parallel stages of one node tick (issue 13):
// dynamics per vehicle, collision broad phase per bucket range, narrow phase per entity / pair.
//
// Contract:
//  * Jobs(n): n threads in all, the calling thread included (n - 1 workers are started; n = 1
//    starts none and runs everything on the caller, the single-threaded path).
//  * for_chunks(count, grain, fn): splits [0, count) into k = chunks(count, grain) contiguous
//    ranges, chunk c = [count * c / k, count * (c + 1) / k), and calls fn(c, begin, end) once
//    for each (chunk 0 on the caller, the others on workers), returning when all are done.
//    The split depends only on count, grain and threads(): a stage whose chunks write only their
//    own outputs (per-chunk buffers, or the slots of their own range), merged afterwards in
//    chunk order, gives the same bytes as one thread walking [0, count) in order.
//  * An exception thrown by fn is rethrown on the caller once every chunk has ended (the one of
//    the lowest chunk when several threw), so an error names the first bad item in index order.
//  * Not reentrant: for_chunks is called from one thread (the tick's), never from inside fn.
//    No allocation per call; workers sleep on a condition variable between calls.
#pragma once
#include <condition_variable>
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

  explicit Jobs(int threads = 1);  // threads clamped to [1, kMaxThreads]
  ~Jobs();
  Jobs(const Jobs&) = delete;
  Jobs& operator=(const Jobs&) = delete;

  int threads() const { return threads_; }
  // Caps every stage's grain (0 = no cap): tests set 1 so that every stage splits as finely as
  // the thread count allows, whatever its size.
  void set_max_grain(size_t g) { max_grain_ = g; }
  // How many chunks for_chunks splits `count` items into: min(threads, count / grain), >= 1.
  int chunks(size_t count, size_t grain) const {
    size_t g = grain ? grain : 1;
    if (max_grain_ && g > max_grain_) g = max_grain_;
    const size_t k = count / g;
    return k < 1 ? 1 : k > static_cast<size_t>(threads_) ? threads_ : static_cast<int>(k);
  }
  static size_t chunk_begin(size_t count, int c, int k) { return count * static_cast<size_t>(c) / static_cast<size_t>(k); }

  template <class F>
  void for_chunks(size_t count, size_t grain, F&& fn) {
    const int k = chunks(count, grain);
    if (k == 1) {
      fn(0, size_t{0}, count);
      return;
    }
    run(count, k, &call<std::remove_reference_t<F>>, &fn);
  }

 private:
  using Call = void (*)(void* ctx, int chunk, size_t begin, size_t end);
  template <class F>
  static void call(void* ctx, int c, size_t b, size_t e) {
    (*static_cast<F*>(ctx))(c, b, e);
  }
  void run(size_t count, int k, Call fn, void* ctx);
  void work(int worker);
  void do_chunk(int c);

  int threads_ = 1;
  size_t max_grain_ = 0;
  std::vector<std::thread> workers_;
  std::mutex mu_;
  std::condition_variable wake_, done_;
  // The job being run (written under mu_ before the generation changes).
  Call fn_ = nullptr;
  void* ctx_ = nullptr;
  size_t count_ = 0;
  int k_ = 0;
  unsigned long generation_ = 0;
  int pending_ = 0;
  bool stop_ = false;
  std::vector<std::exception_ptr> errors_;  // per chunk
};

}  // namespace npsnet::core
