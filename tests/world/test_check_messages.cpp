// Bad input gives FILE:LINE: field: message, one test per kind of mistake.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "support/fixture.hpp"

using namespace npsnet;

namespace {

// A 200 m x 200 m .asc terrain (no CRS: local metres), height 100 with a pond (50 m) in the
// south-west 50 m x 50 m.
std::filesystem::path small_terrain() {
  std::ostringstream s;
  s << "ncols 21\nnrows 21\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n";
  for (int r = 0; r < 21; ++r) {
    const int j = 20 - r;  // first row written is the north edge
    for (int i = 0; i < 21; ++i) s << ((i <= 5 && j <= 5) ? 50 : 100) << (i < 20 ? " " : "\n");
  }
  return test::write_file("small.asc", s.str());
}

std::string scenario(const std::string& body, const std::string& name = "s.toml") {
  const auto t = small_terrain();
  const std::string head = "[world]\nterrain = \"" + t.filename().string() + "\"\nkinds = \"" +
                           world::default_kinds_file().string() + "\"\nwater_level_m = 80.0\n";
  return test::write_file(name, head + body).string();
}

// Loads and builds; returns every problem as text.
std::vector<std::string> problems_of(const std::string& file) {
  try {
    const auto sc = world::load_scenario(file);
    (void)world::build_world(sc);
  } catch (const world::InputError& e) {
    std::vector<std::string> out;
    for (const auto& p : e.problems()) out.push_back(p.str());
    return out;
  }
  return {};
}

const char* kTank = "[[vehicle]]\nid = \"%s\"\nkind = \"%s\"\nposition_m = [%s]\n";
std::string vehicle(const std::string& id, const std::string& kind, const std::string& pos) {
  char buf[256];
  std::snprintf(buf, sizeof buf, kTank, id.c_str(), kind.c_str(), pos.c_str());
  return buf;
}

}  // namespace

TEST(CheckMessages, GoodScenarioHasNoProblems) {
  EXPECT_TRUE(problems_of(scenario(vehicle("t1", "m1a1", "150.0, 150.0"))).empty());
}

TEST(CheckMessages, SyntaxError) {
  const auto f = scenario("[[vehicle]]\nid = \"t1\nkind = \"m1a1\"\n");
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].rfind(f + ":6: syntax: ", 0), 0u) << p[0];
}

TEST(CheckMessages, UnknownKind) {
  const auto f = scenario(vehicle("t1", "m1a2", "150.0, 150.0"));
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].rfind(f + ":5: vehicle[0].kind: unknown kind 'm1a2' (known: ah64, bmp, building,", 0), 0u) << p[0];
}

// A vehicle's DIS Force ID (issue 10, defect 6): friendly (default), opposing or neutral.
TEST(CheckMessages, ForceIsFriendlyOpposingOrNeutral) {
  const auto f = scenario(vehicle("t1", "m1a1", "150.0, 150.0") + "force = \"blue\"\n" +
                          vehicle("t2", "m1a1", "160.0, 150.0") + "force = \"opposing\"\n");
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], f + ":9: vehicle[0].force: must be friendly, opposing or neutral (got 'blue')");
  const auto g = scenario(vehicle("t2", "m1a1", "160.0, 150.0") + "force = \"opposing\"\n", "force2.toml");
  EXPECT_EQ(world::build_world(world::load_scenario(g)).ents.force[0], 2);
}

TEST(CheckMessages, MissingTerrainFile) {
  const auto f = test::write_file("missing.toml", "[world]\nterrain = \"nowhere.tif\"\n").string();
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], f + ":2: world.terrain: file not found: " + (std::filesystem::path(f).parent_path() / "nowhere.tif").string());
}

TEST(CheckMessages, MissingScenarioFile) {
  const auto p = problems_of("/nonexistent/s.toml");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], "/nonexistent/s.toml:0: file: file not found");
}

TEST(CheckMessages, DuplicateId) {
  const auto f = scenario(vehicle("t1", "m1a1", "150.0, 150.0") + vehicle("t1", "m1a1", "160.0, 150.0"));
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], f + ":10: vehicle[1].id: duplicate id 't1'");
}

TEST(CheckMessages, IdLongerThanElevenCharacters) {
  const auto f = scenario(vehicle("abcdefghijkl", "m1a1", "150.0, 150.0"));
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], f + ":6: vehicle[0].id: 'abcdefghijkl' is 12 characters; at most 11 (it travels as the DIS marking)");
}

TEST(CheckMessages, PositionOffTheMap) {
  const auto f = scenario(vehicle("t1", "m1a1", "250.0, 150.0"));
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].rfind(f + ":5: vehicle[0].position_m: (250.000000, 150.000000) is off the map", 0), 0u) << p[0];
}

TEST(CheckMessages, GroundVehicleInWater) {
  const auto f = scenario(vehicle("t1", "m1a1", "10.0, 10.0"));
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], f + ":5: vehicle[0].position_m: a ground vehicle cannot start in water");
}

TEST(CheckMessages, NaN) {
  const auto f = scenario(vehicle("t1", "m1a1", "nan, 150.0"));
  const auto p = problems_of(f);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], f + ":8: vehicle[0].position_m: must be finite (got nan)");
}

TEST(CheckMessages, NegativeMassInKinds) {
  const auto models = world::default_kinds_file().parent_path();
  const auto f = test::write_file("kinds.toml", "[rock]\nmobility = \"fixed\"\nmass_kg = -5.0\nstates = [\"intact\"]\nmodels = [\"" +
                                                    (models / "rock.obj").string() + "\"]\ndis_type = [5,1,0,1,3,0,0]\n").string();
  world::ModelLibrary lib;
  try {
    (void)world::KindTable::load(f, lib);
    FAIL() << "negative mass accepted";
  } catch (const world::InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].str(), f + ":3: rock.mass_kg: must be positive (got -5.000000)");
  }
}

TEST(CheckMessages, SensorRangeInKinds) {
  const auto models = world::default_kinds_file().parent_path();
  auto kind = [&](const std::string& extra) {
    return "[jeep]\nmobility = \"ground\"\nmass_kg = 2500.0\nstates = [\"intact\"]\nmodels = [\"" +
           (models / "hmmwv.obj").string() + "\"]\ndis_type = [1,1,225,6,1,0,0]\n" + extra;
  };
  world::ModelLibrary lib;
  // Not given: the default of the kind's mobility (ground 5 km); given: as written.
  EXPECT_EQ(world::KindTable::load(test::write_file("k1.toml", kind("")), lib)[0].sensor_range_m, 5000.0);
  EXPECT_EQ(world::KindTable::load(test::write_file("k2.toml", kind("sensor_range_m = 7500.0\n")), lib)[0].sensor_range_m,
            7500.0);
  const auto f = test::write_file("k3.toml", kind("sensor_range_m = -1.0\n")).string();
  try {
    (void)world::KindTable::load(f, lib);
    FAIL() << "negative sensor range accepted";
  } catch (const world::InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].str(), f + ":7: jeep.sensor_range_m: must not be negative");
  }
}

TEST(CheckMessages, ObjectsCsvLineErrors) {
  const auto f = test::write_file("objs.csv", "id,kind,x_m,y_m,heading_deg\nT1,tree,150,150,0\nT1,tree,160,150,0\n"
                                              "T2,oak,150,150,0\nT3,tree,nan,150,0\nT4,tree,500,150,0\nT5,tree,10,10,0\n").string();
  world::World w = test::flat_world();
  w.terrain = world::Terrain::load(small_terrain(), {35.98, -121.25, 0});
  std::vector<world::Problem> probs;
  world::load_objects_csv(f, w.kinds, w.terrain, 80.0, w.fixed, probs);
  ASSERT_EQ(probs.size(), 5u);
  EXPECT_EQ(probs[0].str(), f + ":3: id: duplicate id 'T1'");
  EXPECT_EQ(probs[1].str().rfind(f + ":4: kind: unknown kind 'oak'", 0), 0u);
  EXPECT_EQ(probs[2].str(), f + ":5: x_m: 'nan' is not a finite number");
  EXPECT_EQ(probs[3].str(), f + ":6: position: (500, 150) is off the map");
  EXPECT_EQ(probs[4].str(), f + ":7: position: (10, 10) is in water");
  EXPECT_EQ(w.fixed.size(), 1u);  // only the first T1 is taken
}
