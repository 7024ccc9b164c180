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
