// Fuzz target (b): a scenario TOML through what `npsnet check` and `npsnet run` do with it:
// load_scenario_text (syntax, fields, ids, fire references) and, when that passes,
// build_world (terrain, kinds, models, objects, placement). The bytes stand for the file
// fuzz/data/scenarios/fuzz.toml, whose relative paths reach the small fixture world.
// Rejection (InputError) is the expected answer to bad input; anything else escaping is a bug.
#include "fuzz_support.hpp"
#include "world/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  static const auto file = fuzz::data_dir() / "scenarios" / "fuzz.toml";
  try {
    const world::Scenario s = world::load_scenario_text(fuzz::text(data, size), file);
    // Up to 1,000,000 background vehicles is a valid scenario, but one that takes seconds to
    // place: past 2,000 only the loading is fuzzed, so that a slow input is not a "timeout".
    if (s.background_vehicles > 2000) return 0;
    const world::World w = world::build_world(s);
    (void)w;
  } catch (const world::InputError&) {
  }
  return 0;
}
