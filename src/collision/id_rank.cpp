// Ranking of entity ids, whole or by the slots made since the last call (id_rank.hpp).
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

namespace {
// (id, index) order: the prefix keys decide most comparisons (id_rank.hpp), then the strings.
struct Less {
  const std::vector<std::string>& ids;
  const std::vector<uint64_t>& key;
  bool operator()(uint32_t x, uint32_t y) const {
    if (key[x] != key[y]) return key[x] < key[y];
    const int c = ids[x].compare(ids[y]);
    return c != 0 ? c < 0 : x < y;
  }
};
}  // namespace

void IdRank::update(const std::vector<std::string>& ids) {
  const size_t n = ids.size();
  // Room for the rounds to come: no reallocation (a copy of every array) at the first of them.
  const size_t room = n + n / 8 + 64;
  key_.reserve(room), by_.reserve(room), rank_.reserve(room), dirty_.reserve(room);
  key_.resize(n);
  by_.resize(n);
  for (size_t i = 0; i < n; ++i) key_[i] = id_prefix_key(ids[i]), by_[i] = static_cast<uint32_t>(i);
  std::sort(by_.begin(), by_.end(), Less{ids, key_});
  rank_.resize(n);
  for (uint32_t r = 0; r < n; ++r) rank_[by_[r]] = r;
}

void IdRank::update(const std::vector<std::string>& ids, std::span<const uint32_t> made) {
  const size_t n = ids.size(), old = rank_.size();
  if (old > n || old == 0) return update(ids);  // a smaller table, or never ranked: from scratch
  const Less less{ids, key_};
  // The slots to place: those made (once each) and those appended.
  dirty_.assign(n, 0);
  fresh_.clear();
  for (uint32_t i : made)
    if (i < n && !dirty_[i]) dirty_[i] = 1, fresh_.push_back(i);
  for (size_t i = old; i < n; ++i)
    if (!dirty_[i]) dirty_[i] = 1, fresh_.push_back(static_cast<uint32_t>(i));
  if (fresh_.empty()) return;
  key_.resize(n);
  for (uint32_t i : fresh_) key_[i] = id_prefix_key(ids[i]);
  std::sort(fresh_.begin(), fresh_.end(), less);
  // Out of the kept order: the made slots that had a place (their old ids). first: the lowest
  // place that moves.
  size_t first = by_.size();
  for (uint32_t i : fresh_)
    if (i < old) first = std::min<size_t>(first, rank_[i]);
  if (first < by_.size())
    by_.erase(std::remove_if(by_.begin() + static_cast<std::ptrdiff_t>(first), by_.end(), [&](uint32_t i) { return dirty_[i]; }),
              by_.end());
  if (fresh_.size() > kManyMade) {  // many: one merge
    kept_.assign(by_.begin(), by_.end());
    by_.resize(n);
    std::merge(kept_.begin(), kept_.end(), fresh_.begin(), fresh_.end(), by_.begin(), less);
    first = 0;
  } else {  // few: each into its place, the largest first (the places of the smaller hold)
    for (size_t f = fresh_.size(); f-- > 0;) {
      const auto at = std::lower_bound(by_.begin(), by_.end(), fresh_[f], less);
      first = std::min<size_t>(first, static_cast<size_t>(at - by_.begin()));
      by_.insert(at, fresh_[f]);
    }
  }
  rank_.resize(n);
  for (size_t r = first; r < n; ++r) rank_[by_[r]] = static_cast<uint32_t>(r);
}

std::vector<uint32_t> rank_ids_brute(const std::vector<std::string>& ids) {
  std::vector<uint32_t> by(ids.size()), out(ids.size());
  for (uint32_t i = 0; i < by.size(); ++i) by[i] = i;
  std::sort(by.begin(), by.end(), [&](uint32_t x, uint32_t y) { return ids[x] != ids[y] ? ids[x] < ids[y] : x < y; });
  for (uint32_t r = 0; r < by.size(); ++r) out[by[r]] = r;
  return out;
}

}  // namespace npsnet::collision
