// The order of entity ids that contacts and pairs are sorted by (collision.hpp: by integers, not
// by storage index nor by comparing strings in the hot loop).
// IdRank: ranks()[i] = the place of (ids[i], i) among all (id, index) pairs in ascending order
// (std::string <, then index).
//  update(ids): ranks every id (a sort of all n).
//  update(ids, made): after a change whose only new or replaced ids are the slots in `made`
//    (world::Entities::made_since: a round fired, a slot reclaimed) and slots appended past the
//    last call's size: each such slot leaves its old place and is put in its new one by binary
//    search, then the ranks from the first place that moved on are rewritten. O(k log n) string
//    comparisons and O(n) plain moves for k slots (was: every id compared with its last value
//    and one O(n) merge, 0.65 ms a round at 100,000 vehicles; the first round 5.3 ms). Many
//    slots at once (more than kManyMade): one sort of those and one merge.
// The sort compares 8-byte prefix keys first (id_prefix_key: the id's first 8 bytes, big-endian,
// zero-padded; a smaller key means a smaller id in std::string's order, unsigned bytes, a prefix
// first) and the strings only where the keys are equal: the same order, without a memcmp per
// comparison (the first tick ranks all 40,303 fixed ids of the default world).
// rank_ids_brute is the plain full sort the tests compare it with. Buffers are reused.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace npsnet::collision {

class IdRank {
 public:
  void update(const std::vector<std::string>& ids);
  void update(const std::vector<std::string>& ids, std::span<const uint32_t> made);
  const std::vector<uint32_t>& ranks() const { return rank_; }
  static constexpr size_t kManyMade = 16;

 private:
  std::vector<uint32_t> by_;  // indices in (id, index) order
  std::vector<uint32_t> kept_, fresh_, rank_;
  std::vector<uint8_t> dirty_;
  std::vector<uint64_t> key_;  // id_prefix_key of each id at the last update
};

uint64_t id_prefix_key(const std::string& id);

std::vector<uint32_t> rank_ids_brute(const std::vector<std::string>& ids);

}  // namespace npsnet::collision
