// The order of entity ids that contacts and pairs are sorted by (collision.hpp: by integers, not
// by storage index nor by comparing strings in the hot loop).
// IdRank::update(ids): ranks()[i] = the place of (ids[i], i) among all (id, index) pairs in
// ascending order (std::string <, then index). After a change (a round fired: a new entity or a
// reclaimed slot with a new id) only the slots whose id differs from the previous call, or are
// new, are sorted and merged into the kept order: O(n) equality checks and one O(n) merge,
// instead of sorting all n strings again for every shot (issue 13's profile at 100,000 vehicles).
// The sort compares 8-byte prefix keys first (id_prefix_key: the id's first 8 bytes, big-endian,
// zero-padded; a smaller key means a smaller id in std::string's order, unsigned bytes, a prefix
// first) and the strings only where the keys are equal: the same order, without a memcmp per
// comparison (the first tick ranks all 40,303 fixed ids of the default world).
// rank_ids_brute is the plain full sort the tests compare it with. Buffers are reused.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace npsnet::collision {

class IdRank {
 public:
  void update(const std::vector<std::string>& ids);
  const std::vector<uint32_t>& ranks() const { return rank_; }

 private:
  std::vector<std::string> seen_;  // ids at the last update
  std::vector<uint32_t> by_;       // indices in (id, index) order
  std::vector<uint32_t> kept_, fresh_, rank_;
  std::vector<uint8_t> dirty_;
  std::vector<uint64_t> key_;  // id_prefix_key of each id at the last update
};

uint64_t id_prefix_key(const std::string& id);

std::vector<uint32_t> rank_ids_brute(const std::vector<std::string>& ids);

}  // namespace npsnet::collision
