// Fuzz target (e): an OBJ model through load_obj_text, as a kinds file loads each model. The
// bytes stand for models/fuzz.obj in the source tree, so `mtllib materials.mtl` reads the
// bundled materials.
#include "fuzz_support.hpp"
#include "world/error.hpp"
#include "world/model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  static const auto file = fuzz::source_dir() / "models" / "fuzz.obj";
  try {
    const world::Model m = world::load_obj_text(fuzz::text(data, size), file);
    (void)m;
  } catch (const world::InputError&) {
  }
  return 0;
}
