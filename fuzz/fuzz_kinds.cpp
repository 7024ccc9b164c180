// Fuzz target (c): a kinds TOML through KindTable::load_text, as `npsnet check` and
// build_world load it. The bytes stand for models/fuzz-kinds.toml in the source tree, so model
// names resolve against the bundled models; the ModelLibrary is kept across inputs (a model
// file loads once per process, as in a run), which keeps this target fast.
#include "fuzz_support.hpp"
#include "world/kinds.hpp"
#include "world/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  static const auto file = fuzz::source_dir() / "models" / "fuzz-kinds.toml";
  static world::ModelLibrary models;
  try {
    const world::KindTable k = world::KindTable::load_text(fuzz::text(data, size), file, models);
    (void)k.names();
  } catch (const world::InputError&) {
  }
  return 0;
}
