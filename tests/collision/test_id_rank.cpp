// IdRank (collision/id_rank.hpp), the incremental id order, against the plain full sort: random
// tables where rounds are made (new ids appended) and slots reclaimed (an id replaced), a few or
// many at a time, with duplicate ids (the index breaks the tie) and a table that shrinks; and
// world::Entities::made_since, which tells the Detector which slots to place.
#include <gtest/gtest.h>

#include <random>

#include "collision/id_rank.hpp"
#include "support/fixture.hpp"
#include "world/world.hpp"

using npsnet::collision::IdRank;
using npsnet::collision::rank_ids_brute;

TEST(IdRank, AgreesWithTheFullSortAsIdsAreAddedAndReplaced) {
  std::mt19937 rng(13);
  auto name = [&] { return npsnet::test::numbered("v", rng() % 5000); };  // duplicates on purpose
  std::vector<std::string> ids;
  for (int i = 0; i < 3000; ++i) ids.push_back(name());
  IdRank r;
  r.update(ids);
  ASSERT_EQ(r.ranks(), rank_ids_brute(ids));
  std::vector<uint32_t> made;
  for (int step = 0; step < 400; ++step) {
    made.clear();
    // Most steps make a few entities; some make many at once (more than kManyMade: the merge).
    const int changes = step % 50 == 7 ? 40 : static_cast<int>(rng() % 4);
    for (int c = 0; c < changes; ++c) {
      const int what = static_cast<int>(rng() % 3);
      const uint32_t slot = static_cast<uint32_t>(rng() % ids.size());
      if (what == 0) ids.push_back(npsnet::test::numbered("m", step)), made.push_back(static_cast<uint32_t>(ids.size() - 1));  // a round fired
      else if (what == 1) ids[slot] = npsnet::test::numbered("m", step), made.push_back(slot);  // a slot reclaimed
      else ids[slot] = name(), made.push_back(slot), made.push_back(slot);  // named again, listed twice
    }
    if (step % 3 == 0) ids.push_back(name());  // appended without being listed: still placed
    r.update(ids, made);
    ASSERT_EQ(r.ranks(), rank_ids_brute(ids)) << "step " << step << ", " << changes << " made";
  }
  ids.resize(100);  // a smaller table: ranked from scratch
  r.update(ids, {});
  EXPECT_EQ(r.ranks(), rank_ids_brute(ids));
  ids.clear();
  r.update(ids);
  EXPECT_TRUE(r.ranks().empty());
}

// The entity table says which slots were made since a creation count, for its own lineage only
// and only as far back as it remembers; the Detector's ranks follow rounds fired and reclaimed.
TEST(IdRank, EntitiesSayWhichSlotsWereMadeSince) {
  npsnet::world::Entities ents;
  for (int i = 0; i < 10; ++i) ents.add(npsnet::test::numbered("v", i), 0, npsnet::Vec3::Zero(), 0, 1);
  const int64_t at = ents.created;
  ents.add("m1", 0, npsnet::Vec3::Zero(), 0, 1);
  ents.reset(3, "m2", 0, npsnet::Vec3::Zero(), 0, 1);
  std::vector<uint32_t> made;
  ASSERT_TRUE(ents.made_since(ents.lineage.v, at, made));
  EXPECT_EQ(made, (std::vector<uint32_t>{10, 3}));
  made.clear();
  EXPECT_TRUE(ents.made_since(ents.lineage.v, ents.created, made));
  EXPECT_TRUE(made.empty());
  const npsnet::world::Entities copy = ents;
  EXPECT_NE(copy.lineage.v, ents.lineage.v) << "a copy is another table";
  EXPECT_FALSE(copy.made_since(ents.lineage.v, at, made));
  for (int i = 0; i < npsnet::world::Entities::kMadeMemory; ++i) ents.reset(0, npsnet::test::numbered("r", i), 0, npsnet::Vec3::Zero(), 0, 1);
  EXPECT_FALSE(ents.made_since(ents.lineage.v, at, made)) << "more made than it remembers";
  EXPECT_TRUE(ents.made_since(ents.lineage.v, ents.created - npsnet::world::Entities::kMadeMemory, made));
  EXPECT_EQ(made.size(), static_cast<size_t>(npsnet::world::Entities::kMadeMemory));
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
      if (ki < kj) {
        ASSERT_LT(ids[i], ids[j]) << i << " " << j;
      }
    }
  IdRank r;
  r.update(ids);
  EXPECT_EQ(r.ranks(), rank_ids_brute(ids));
}
