// Incremental ranking of entity ids (id_rank.hpp).
#include "collision/id_rank.hpp"

#include <algorithm>
#include <cstring>

namespace npsnet::collision {

uint64_t id_prefix_key(const std::string& s) {
  unsigned char b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::memcpy(b, s.data(), s.size() < 8 ? s.size() : 8);
  uint64_t k = 0;
  for (unsigned char c : b) k = k << 8 | c;  // big-endian: the first byte decides first
  return k;
}

void IdRank::update(const std::vector<std::string>& ids) {
  const size_t n = ids.size();
  // The prefix keys decide most comparisons (id_rank.hpp); equal keys fall back to the strings.
  auto less = [&](uint32_t x, uint32_t y) {
    if (key_[x] != key_[y]) return key_[x] < key_[y];
    const int c = ids[x].compare(ids[y]);
    return c != 0 ? c < 0 : x < y;
  };
  if (seen_.size() > n) seen_.clear(), by_.clear();  // the table shrank: rank from scratch
  fresh_.clear();
  dirty_.assign(n, 0);
  for (size_t i = 0; i < n; ++i)
    if (i >= seen_.size() || ids[i] != seen_[i]) fresh_.push_back(static_cast<uint32_t>(i)), dirty_[i] = 1;
  if (fresh_.empty() && rank_.size() == n) return;
  key_.resize(n);
  for (uint32_t i : fresh_) key_[i] = id_prefix_key(ids[i]);
  kept_.clear();
  for (uint32_t i : by_)
    if (!dirty_[i]) kept_.push_back(i);
  std::sort(fresh_.begin(), fresh_.end(), less);
  by_.resize(kept_.size() + fresh_.size());
  std::merge(kept_.begin(), kept_.end(), fresh_.begin(), fresh_.end(), by_.begin(), less);
  rank_.resize(n);
  for (uint32_t r = 0; r < by_.size(); ++r) rank_[by_[r]] = r;
  seen_.resize(n);
  for (uint32_t i : fresh_) seen_[i] = ids[i];
}

std::vector<uint32_t> rank_ids_brute(const std::vector<std::string>& ids) {
  std::vector<uint32_t> by(ids.size()), out(ids.size());
  for (uint32_t i = 0; i < by.size(); ++i) by[i] = i;
  std::sort(by.begin(), by.end(), [&](uint32_t x, uint32_t y) { return ids[x] != ids[y] ? ids[x] < ids[y] : x < y; });
  for (uint32_t r = 0; r < by.size(); ++r) out[by[r]] = r;
  return out;
}

}  // namespace npsnet::collision
