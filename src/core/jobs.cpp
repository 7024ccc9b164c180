// Worker pool of the tick (jobs.hpp): worker w runs chunk w of each job; the caller runs chunk 0.
#include "core/jobs.hpp"

#include <algorithm>

namespace npsnet::core {

int Jobs::default_threads() {
  const unsigned h = std::thread::hardware_concurrency();
  return std::clamp(static_cast<int>(h), 1, kDefaultCap);
}

Jobs::Jobs(int threads) : threads_(std::clamp(threads, 1, kMaxThreads)), errors_(threads_) {
  workers_.reserve(threads_ - 1);
  for (int w = 1; w < threads_; ++w) workers_.emplace_back([this, w] { work(w); });
}

Jobs::~Jobs() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void Jobs::do_chunk(int c) {
  try {
    fn_(ctx_, c, chunk_begin(count_, c, k_), chunk_begin(count_, c + 1, k_));
  } catch (...) {
    errors_[c] = std::current_exception();
  }
}

void Jobs::work(int w) {
  unsigned long seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mu_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      if (w >= k_) continue;  // this job has fewer chunks than threads
    }
    do_chunk(w);
    {
      std::lock_guard<std::mutex> lock(mu_);
      if (--pending_ == 0) done_.notify_one();
    }
  }
}

void Jobs::run(size_t count, int k, Call fn, void* ctx) {
  {
    std::lock_guard<std::mutex> lock(mu_);
    fn_ = fn, ctx_ = ctx, count_ = count, k_ = k;
    pending_ = k - 1;
    std::fill(errors_.begin(), errors_.end(), nullptr);
    ++generation_;
  }
  wake_.notify_all();
  do_chunk(0);
  {
    std::unique_lock<std::mutex> lock(mu_);
    done_.wait(lock, [&] { return pending_ == 0; });
  }
  for (int c = 0; c < k; ++c)
    if (errors_[c]) std::rethrow_exception(errors_[c]);
}

}  // namespace npsnet::core
