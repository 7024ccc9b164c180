// Fuzz target (d): a fixed-object CSV (id,kind,x_m,y_m[,heading_deg]) through
// load_objects_csv_text, against the bundled kinds and the fixture terrain (water level 200 m,
// as in the default scenario). (The gridsquare index built from the objects is fuzzed with the
// whole world by fuzz_scenario.)
#include "fuzz_support.hpp"
#include "world/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  static world::ModelLibrary models;
  static const world::KindTable kinds = world::KindTable::load(world::default_kinds_file(), models);
  static const world::Terrain terrain =
      world::Terrain::load(fuzz::data_dir() / "terrain" / "default.tif", {35.98, -121.25, 0.0});
  static const auto file = fuzz::data_dir() / "terrain" / "fuzz-objects.csv";
  world::FixedObjects objects;
  std::vector<world::Problem> problems;
  try {
    world::load_objects_csv_text(fuzz::text(data, size), file, kinds, terrain, 200.0, objects, problems);
  } catch (const world::InputError&) {
  }
  for (const auto& p : problems) (void)p.str();
  return 0;
}
