// IdRank (collision/id_rank.hpp), the incremental id order, against the plain full sort: random
// tables where rounds are made (new ids appended) and slots reclaimed (an id replaced), with
// duplicate ids (the index breaks the tie) and a table that shrinks.
#include <gtest/gtest.h>

#include <random>

#include "collision/id_rank.hpp"

using npsnet::collision::IdRank;
using npsnet::collision::rank_ids_brute;

TEST(IdRank, AgreesWithTheFullSortAsIdsAreAddedAndReplaced) {
  std::mt19937 rng(13);
  auto name = [&] { return "v" + std::to_string(rng() % 5000); };  // duplicates on purpose
  std::vector<std::string> ids;
  for (int i = 0; i < 3000; ++i) ids.push_back(name());
  IdRank r;
  r.update(ids);
  ASSERT_EQ(r.ranks(), rank_ids_brute(ids));
  for (int step = 0; step < 200; ++step) {
    const int what = static_cast<int>(rng() % 4);
    if (what == 0) ids.push_back("m" + std::to_string(step));             // a round fired
    else if (what == 1) ids[rng() % ids.size()] = "m" + std::to_string(step);  // a slot reclaimed
    else if (what == 2) ids[rng() % ids.size()] = name();
    // what == 3: nothing changed
    r.update(ids);
    ASSERT_EQ(r.ranks(), rank_ids_brute(ids)) << "step " << step;
  }
  ids.resize(100);  // a smaller table
  r.update(ids);
  EXPECT_EQ(r.ranks(), rank_ids_brute(ids));
  ids.clear();
  r.update(ids);
  EXPECT_TRUE(r.ranks().empty());
}

// The prefix keys (id_prefix_key) order ids as std::string does where the first 8 bytes differ:
// shorter ids, ids alike in their first 8 bytes, embedded NUL bytes and bytes past 0x7f.
TEST(IdRank, PrefixKeysKeepTheStringOrder) {
  std::mt19937 rng(7);
  const char alphabet[] = {'\0', '\x01', '0', '9', 'a', 'z', '\x7f', '\x80', '\xff'};
  std::vector<std::string> ids = {"", std::string(1, '\0'), std::string(9, '\0'), "tree0000", "tree00000", "tree0000\x01",
                                  "tree0000\xff", "tree000", "\xff", "bg00001", std::string("bg00001\0x", 9)};
  for (int i = 0; i < 4000; ++i) {
    std::string s(rng() % 12, 'a');
    for (char& c : s) c = alphabet[rng() % sizeof alphabet];
    ids.push_back(i % 3 ? s : "prefix12" + s);
  }
  for (size_t i = 0; i < ids.size(); ++i)
    for (size_t j = 0; j < ids.size(); j += 37) {
      const uint64_t ki = npsnet::collision::id_prefix_key(ids[i]), kj = npsnet::collision::id_prefix_key(ids[j]);
      if (ki < kj) ASSERT_LT(ids[i], ids[j]) << i << " " << j;
    }
  IdRank r;
  r.update(ids);
  EXPECT_EQ(r.ranks(), rank_ids_brute(ids));
}
