// Hashed moving grid, static sphere grid, brute-force reference (broadphase.hpp).
#include "collision/broadphase.hpp"

#include <algorithm>

namespace npsnet::collision {

Box swept_box(const Vec3& c0, const Vec3& c1, double r) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = static_cast<float>(std::min(c0[k], c1[k]) - r);
    b.hi[k] = static_cast<float>(std::max(c0[k], c1[k]) + r);
  }
  return b;
}

namespace {
inline uint32_t hash_cell(int32_t x, int32_t y, uint32_t mask) {
  return (static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u) & mask;
}
}  // namespace

void MovingGrid::pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out) {
  out.clear();
  const uint32_t n = static_cast<uint32_t>(boxes.size());
  large_.clear();
  if (n < 2) return;
  // Cell: the largest extent among ordinary boxes (extent <= 4x the mean).
  double mean = 0;
  for (const Box& b : boxes) mean += std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
  mean /= n;
  const double cap = 4 * mean;
  double cell = 0;
  for (const Box& b : boxes) {
    const double e = std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
    if (e <= cap) cell = std::max(cell, e);
  }
  cell_ = std::max(cell, 1e-3);
  const double inv = 1.0 / cell_;
  uint32_t nb = 1;
  while (nb < 2 * n) nb <<= 1;
  const uint32_t mask = nb - 1;
  bucket_of_.resize(n);
  cx_.resize(n);
  cy_.resize(n);
  start_.assign(nb + 1, 0);
  for (uint32_t i = 0; i < n; ++i) {
    const Box& b = boxes[i];
    const double e = std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
    if (e > cap) {
      large_.push_back(i);
      bucket_of_[i] = ~0u;
      continue;
    }
    cx_[i] = static_cast<int32_t>(std::floor(0.5 * (double(b.lo[0]) + b.hi[0]) * inv));
    cy_[i] = static_cast<int32_t>(std::floor(0.5 * (double(b.lo[1]) + b.hi[1]) * inv));
    const uint32_t h = hash_cell(cx_[i], cy_[i], mask);
    bucket_of_[i] = h;
    ++start_[h + 1];
  }
  for (uint32_t h = 0; h < nb; ++h) start_[h + 1] += start_[h];
  const uint32_t placed = start_[nb];
  items_.resize(placed);
  sorted_.resize(placed);
  // Fill in increasing id order: each bucket lists its ids ascending.
  {
    // reuse cx_-sized scratch: next free slot per bucket, taken from start_ (restored below)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t h = bucket_of_[i];
      if (h == ~0u) continue;
      const uint32_t slot = start_[h]++;
      items_[slot] = i;
      sorted_[slot] = boxes[i];
    }
    for (uint32_t h = nb; h > 0; --h) start_[h] = start_[h - 1];
    start_[0] = 0;
  }
  // Ordinary vs ordinary: the 3 x 3 cells around each box, distinct buckets only, j > i.
  for (uint32_t i = 0; i < n; ++i) {
    if (bucket_of_[i] == ~0u) continue;
    const Box& bi = boxes[i];
    uint32_t seen[9];
    int ns = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const uint32_t h = hash_cell(cx_[i] + dx, cy_[i] + dy, mask);
        bool dup = false;
        for (int s = 0; s < ns; ++s) dup |= seen[s] == h;
        if (dup) continue;
        seen[ns++] = h;
        for (uint32_t k = start_[h]; k < start_[h + 1]; ++k) {
          const uint32_t j = items_[k];
          if (j <= i) continue;
          if (overlap(bi, sorted_[k])) out.emplace_back(i, j);
        }
      }
  }
  // Large boxes against every box (each pair once).
  for (uint32_t l : large_) {
    for (uint32_t j = 0; j < n; ++j) {
      if (j == l || (bucket_of_[j] == ~0u && j < l)) continue;  // large-large pairs once
      if (overlap(boxes[l], boxes[j])) out.emplace_back(std::min(l, j), std::max(l, j));
    }
  }
  // Pairs per i come out grouped by bucket; sort for a canonical order.
  std::sort(out.begin(), out.end());
}

void brute_pairs(const std::vector<Box>& boxes, std::vector<std::pair<uint32_t, uint32_t>>& out) {
  out.clear();
  for (uint32_t i = 0; i < boxes.size(); ++i)
    for (uint32_t j = i + 1; j < boxes.size(); ++j)
      if (overlap(boxes[i], boxes[j])) out.emplace_back(i, j);
}

void FixedGrid::build(const std::vector<Vec3>& centres, const std::vector<float>& radii, double width_m,
                      double depth_m, double cell_m) {
  cell_ = cell_m;
  cols_ = std::max(1, static_cast<int>(std::ceil(width_m / cell_m)));
  rows_ = std::max(1, static_cast<int>(std::ceil(depth_m / cell_m)));
  const size_t ncell = static_cast<size_t>(cols_) * rows_;
  const size_t n = centres.size();
  x_.resize(n);
  std::vector<Item> objs(n);
  for (size_t k = 0; k < n; ++k) {
    objs[k] = {static_cast<float>(centres[k].x()), static_cast<float>(centres[k].y()),
               static_cast<float>(centres[k].z()), radii[k], static_cast<uint32_t>(k)};
    x_[k] = objs[k].x;
  }
  start_.assign(ncell + 1, 0);
  auto each_cell = [&](const Item& it, auto&& f) {
    const int i0 = col(it.x - it.r), i1 = col(it.x + it.r), j0 = row(it.y - it.r), j1 = row(it.y + it.r);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) f(static_cast<size_t>(j) * cols_ + i);
  };
  for (const Item& it : objs) each_cell(it, [&](size_t c) { ++start_[c + 1]; });
  for (size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  items_.resize(start_[ncell]);
  std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
  for (const Item& it : objs) each_cell(it, [&](size_t c) { items_[fill[c]++] = it; });
}

}  // namespace npsnet::collision
