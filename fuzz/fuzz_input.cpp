// Fuzz target (f): an `--input` action file (JSON Lines) through read_actions_text, as
// `npsnet run --input FILE` reads it, then every action written back as `--record-input` writes
// it (to_json(...).dump()).
#include "fuzz_support.hpp"
#include "input/action_file.hpp"
#include "world/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  try {
    for (const auto& a : input::read_actions_text(fuzz::text(data, size), "fuzz-input.jsonl"))
      (void)input::to_json(a).dump();
  } catch (const world::InputError&) {
  }
  return 0;
}
