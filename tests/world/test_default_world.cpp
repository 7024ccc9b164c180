// The bundled default world (terrain/default.tif, terrain/default-objects.csv): Table 1 of the
// thesis reproduced exactly, objects on dry land and off the proving ground, the lake and the
// proving ground as promised, and the committed files reproduced by tools/make_default_world.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/dirs.hpp"
#include "core/constants.hpp"
#include "support/scratch.hpp"
#include "world/terrain.hpp"

using namespace npsnet;
namespace th = npsnet::thesis;
namespace fs = std::filesystem;

namespace {

const fs::path kTerrainDir = fs::path(npsnet::dirs::source()) / "terrain";
constexpr double kWaterLevelM = 200.0;  // scenarios/default.toml water_level_m
constexpr double kReserveX0 = 2000, kReserveX1 = 14000, kReserveY0 = 2000, kReserveY1 = 8000;
const geo::Geodetic kOrigin{35.98, -121.25, 0.0};  // Fort Hunter-Liggett, as in the scenario

struct Obj {
  std::string id, kind;
  double x, y, heading;
};

// A tiny CSV reader for this one format; fails the test on any malformed line.
std::vector<Obj> read_objects(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  EXPECT_TRUE(f) << p;
  std::string line;
  std::getline(f, line);
  EXPECT_EQ(line, "id,kind,x_m,y_m,heading_deg");
  std::vector<Obj> out;
  int n = 1;
  while (std::getline(f, line)) {
    ++n;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) fields.push_back(field);
    if (fields.size() != 5) {
      ADD_FAILURE() << p << ":" << n << ": expected 5 fields: " << line;
      continue;
    }
    Obj o{fields[0], fields[1], 0, 0, 0};
    size_t used = 0;
    o.x = std::stod(fields[2], &used);
    EXPECT_EQ(used, fields[2].size()) << n;
    o.y = std::stod(fields[3], &used);
    EXPECT_EQ(used, fields[3].size()) << n;
    o.heading = std::stod(fields[4], &used);
    EXPECT_EQ(used, fields[4].size()) << n;
    out.push_back(o);
  }
  return out;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

class DefaultWorld : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    objects_ = new std::vector<Obj>(read_objects(kTerrainDir / "default-objects.csv"));
    terrain_ = new world::Terrain(world::Terrain::load(kTerrainDir / "default.tif", kOrigin));
  }
  static void TearDownTestSuite() {
    delete objects_;
    delete terrain_;
  }
  static std::vector<Obj>* objects_;
  static world::Terrain* terrain_;
};
std::vector<Obj>* DefaultWorld::objects_ = nullptr;
world::Terrain* DefaultWorld::terrain_ = nullptr;

bool in_reserve(double x, double y) {
  return x >= kReserveX0 && x <= kReserveX1 && y >= kReserveY0 && y <= kReserveY1;
}

}  // namespace

TEST_F(DefaultWorld, Table1CountsPerKind) {
  std::map<std::string, int> n;
  for (const auto& o : *objects_) ++n[o.kind];
  EXPECT_EQ(n.size(), 7u);
  EXPECT_EQ(n["tree"], th::kTable1Trees);
  EXPECT_EQ(n["bush"], th::kTable1Bushes);
  EXPECT_EQ(n["telephone_pole"], th::kTable1TelephonePoles);
  EXPECT_EQ(n["building"], th::kTable1Buildings);
  EXPECT_EQ(n["watertower"], th::kTable1Watertowers);
  EXPECT_EQ(n["bunker"], th::kTable1OtherManMade);
  EXPECT_EQ(n["rock"], th::kTable1OtherNatural);
  EXPECT_EQ(static_cast<int>(objects_->size()), th::kTable1Total);
}

TEST_F(DefaultWorld, Table1PerGridsquare) {
  const int side = th::kGridsquaresPerSide;
  std::vector<int> count(static_cast<size_t>(side) * side, 0);
  for (const auto& o : *objects_) {
    const int gx = static_cast<int>(std::floor(o.x / th::kGridsquareM));
    const int gy = static_cast<int>(std::floor(o.y / th::kGridsquareM));
    ASSERT_TRUE(gx >= 0 && gy >= 0 && gx < side && gy < side) << o.id;
    ++count[static_cast<size_t>(gy) * side + gx];
  }
  EXPECT_EQ(static_cast<int>(count.size()), th::kGridsquaresTotal);
  EXPECT_EQ(*std::min_element(count.begin(), count.end()), th::kTable1MinPerGridsquare);
  EXPECT_EQ(*std::max_element(count.begin(), count.end()), th::kTable1MaxPerGridsquare);
  const auto occupied = std::count_if(count.begin(), count.end(), [](int c) { return c > 0; });
  const double average = static_cast<double>(objects_->size()) / occupied;
  EXPECT_NEAR(std::round(average * 10) / 10, th::kTable1AveragePerGridsquare, 1e-12) << average;

  // Forests: occupied squares mostly have occupied neighbours (uniformly scattered squares at
  // this density would have 8 * 6.5% ~ 0.5 on average).
  long with_neighbours = 0;
  for (int gy = 1; gy + 1 < side; ++gy)
    for (int gx = 1; gx + 1 < side; ++gx) {
      if (!count[static_cast<size_t>(gy) * side + gx]) continue;
      int nb = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          nb += (dx || dy) && count[static_cast<size_t>(gy + dy) * side + gx + dx] > 0;
      with_neighbours += nb >= 4;
    }
  EXPECT_GT(static_cast<double>(with_neighbours) / occupied, 0.6);
}

TEST_F(DefaultWorld, IdsUniqueAndShort) {
  std::set<std::string> ids;
  for (const auto& o : *objects_) {
    EXPECT_FALSE(o.id.empty());
    EXPECT_LE(o.id.size(), 11u) << o.id;
    for (unsigned char c : o.id) EXPECT_TRUE(c > 32 && c < 127) << o.id;
    EXPECT_TRUE(ids.insert(o.id).second) << "duplicate id " << o.id;
    EXPECT_GE(o.heading, 0.0);
    EXPECT_LT(o.heading, 360.0);
  }
}

TEST_F(DefaultWorld, TerrainShape) {
  const world::Terrain& t = *terrain_;
  EXPECT_EQ(t.cols(), 801);
  EXPECT_EQ(t.rows(), 801);
  EXPECT_DOUBLE_EQ(t.spacing_m(), 62.5);
  EXPECT_DOUBLE_EQ(t.width_m(), th::kWorldSizeM);
  EXPECT_DOUBLE_EQ(t.depth_m(), th::kWorldSizeM);
  EXPECT_DOUBLE_EQ(t.origin().lat_deg, kOrigin.lat_deg);  // no CRS: the scenario's origin
  const auto [lo, hi] = std::minmax_element(t.posts().begin(), t.posts().end());
  EXPECT_GE(*lo, 150.0f);
  EXPECT_LE(*hi, 600.0f);
  EXPECT_GT(*hi - *lo, 300.0f);  // hills, not a plain
  // Slopes mostly under 15 degrees: check the normal on a 250 m lattice.
  int steep = 0, total = 0;
  for (double y = 0; y <= 50000; y += 250)
    for (double x = 0; x <= 50000; x += 250) {
      ++total;
      steep += t.normal(x, y).z() < std::cos(15.0 * kPi / 180.0);
    }
  EXPECT_LT(steep, total / 20);
  std::ostringstream size_note;
  size_note << fs::file_size(kTerrainDir / "default.tif");
  RecordProperty("tif_bytes", size_note.str());
  EXPECT_LT(fs::file_size(kTerrainDir / "default.tif"), 3u * 1024 * 1024);
}

TEST_F(DefaultWorld, LakeIsDeepEnoughAndAwayFromTheProvingGround) {
  const world::Terrain& t = *terrain_;
  int below190 = 0, wet = 0;
  for (int j = 0; j < t.rows(); ++j)
    for (int i = 0; i < t.cols(); ++i) {
      const double x = i * t.spacing_m(), y = j * t.spacing_m();
      if (t.post(i, j) < 190.0f) ++below190;
      if (t.post(i, j) < kWaterLevelM) {
        ++wet;
        // All water lies in the lake's box around (25 km, 25 km).
        ASSERT_NEAR(x, 25000.0, 3500.0) << i << " " << j;
        ASSERT_NEAR(y, 25000.0, 2500.0) << i << " " << j;
      }
    }
  EXPECT_GT(below190, 100);
  EXPECT_LT(t.height(25000, 25000), 190.0);
  // About 6 km x 4 km of water: an ellipse of pi * 3 * 2 km^2 ~ 18.8 km^2.
  const double area_km2 = wet * t.spacing_m() * t.spacing_m() / 1e6;
  EXPECT_GT(area_km2, 15.0);
  EXPECT_LT(area_km2, 23.0);
}

TEST_F(DefaultWorld, ProvingGroundClearAndFlat) {
  const world::Terrain& t = *terrain_;
  for (double y = kReserveY0; y <= kReserveY1; y += 50)
    for (double x = kReserveX0; x <= kReserveX1; x += 50) {
      const double h = t.height(x, y);
      ASSERT_GE(h, 250.0) << x << " " << y;
      ASSERT_LE(h, 270.0) << x << " " << y;
      ASSERT_GT(t.normal(x, y).z(), std::cos(3.0 * kPi / 180.0)) << x << " " << y;
    }
  for (const auto& o : *objects_) EXPECT_FALSE(in_reserve(o.x, o.y)) << o.id;
}

TEST_F(DefaultWorld, ObjectsOnDryLandInsideTheMap) {
  const world::Terrain& t = *terrain_;
  for (const auto& o : *objects_) {
    ASSERT_GE(o.x, 1.0) << o.id;
    ASSERT_GE(o.y, 1.0) << o.id;
    ASSERT_LE(o.x, th::kWorldSizeM - 1.0) << o.id;
    ASSERT_LE(o.y, th::kWorldSizeM - 1.0) << o.id;
    ASSERT_GE(t.height(o.x, o.y), kWaterLevelM + 1.0) << o.id << " at " << o.x << ", " << o.y;
  }
}

TEST_F(DefaultWorld, TelephonePolesFollowARoad) {
  std::vector<const Obj*> poles;
  for (const auto& o : *objects_)
    if (o.kind == "telephone_pole") poles.push_back(&o);
  ASSERT_EQ(static_cast<int>(poles.size()), th::kTable1TelephonePoles);
  std::sort(poles.begin(), poles.end(), [](const Obj* a, const Obj* b) { return a->id < b->id; });
  for (size_t k = 1; k < poles.size(); ++k) {
    const double d = std::hypot(poles[k]->x - poles[k - 1]->x, poles[k]->y - poles[k - 1]->y);
    EXPECT_GT(d, 30.0) << poles[k]->id;
    EXPECT_LT(d, 100.0) << poles[k]->id;
    if (k >= 2) {  // the line bends gently, never doubles back
      const double ax = poles[k - 1]->x - poles[k - 2]->x, ay = poles[k - 1]->y - poles[k - 2]->y;
      const double bx = poles[k]->x - poles[k - 1]->x, by = poles[k]->y - poles[k - 1]->y;
      EXPECT_GT((ax * bx + ay * by) / (std::hypot(ax, ay) * std::hypot(bx, by)), std::cos(0.5))
          << poles[k]->id;
    }
  }
}

TEST(DefaultWorldGenerator, ReproducesTheBundledFiles) {
  const fs::path exe = fs::path(npsnet::dirs::binary()) / "tools" / "make_default_world";
  if (!fs::exists(exe)) GTEST_SKIP() << "generator not built: " << exe;
  const fs::path out = npsnet::test::scratch_dir() / "default_world";
  fs::remove_all(out);
  std::string cmd;  // appends: GCC 12 warns falsely on "literal" + std::string
  cmd.append("\"").append(exe.string()).append("\" \"").append(out.string()).append("\" > \"");
  cmd.append(out.string()).append(".log\" 2>&1");
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(out.string() + ".log");
  EXPECT_TRUE(slurp(out / "default-objects.csv") == slurp(kTerrainDir / "default-objects.csv"))
      << "terrain/default-objects.csv differs from the generator's output; regenerate it";
  // The GeoTIFF's bytes depend on the zlib build; its heights must not.
  const auto fresh = world::Terrain::load(out / "default.tif", kOrigin);
  const auto bundled = world::Terrain::load(kTerrainDir / "default.tif", kOrigin);
  EXPECT_TRUE(fresh.posts() == bundled.posts());
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
}
