// Fenwick tree of non-negative weights for sampling an index with probability ~ weight.
// Contract: WeightTree(w) holds the n = w.size() weights; set(i, w) changes one in O(log n);
// total() is their sum; find(target), 0 <= target < total(), is the index whose cumulative range
// holds target (at most n - 1, against rounding: the caller skips an index whose weight is 0).
// The sums run in a fixed order, so the same weights and calls give the same indices everywhere.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace npsnet::default_world {


// Fenwick tree of non-negative weights for sampling an index with probability ~ weight.
class WeightTree {
 public:
  explicit WeightTree(const std::vector<double>& w) : n_(w.size()), t_(w.size() + 1, 0.0), w_(w) {
    for (size_t i = 0; i < n_; ++i) add(i, w[i]);
  }
  void set(size_t i, double w) {
    add(i, w - w_[i]);
    w_[i] = w;
  }
  double weight(size_t i) const { return w_[i]; }
  double total() const {
    double s = 0;
    for (size_t i = n_; i > 0; i -= i & (~i + 1)) s += t_[i];
    return s;
  }
  // The index whose cumulative range holds `target` (0 <= target < total).
  size_t find(double target) const {
    size_t pos = 0;
    size_t step = 1;
    while (step * 2 <= n_) step *= 2;
    for (; step; step /= 2) {
      if (pos + step <= n_ && t_[pos + step] <= target) {
        pos += step;
        target -= t_[pos];
      }
    }
    return std::min(pos, n_ - 1);
  }

 private:
  void add(size_t i, double d) {
    for (size_t k = i + 1; k <= n_; k += k & (~k + 1)) t_[k] += d;
  }
  size_t n_;
  std::vector<double> t_, w_;
};

}  // namespace npsnet::default_world
