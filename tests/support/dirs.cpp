// support/dirs.hpp: the generated header's paths, in the one object that depends on them.
#include "support/dirs.hpp"

#include "npsnet_dirs.hpp"

namespace npsnet::dirs {
const char* source() { return NPSNET_SOURCE_DIR; }
const char* binary() { return NPSNET_BINARY_DIR; }
const char* fuzz_data() { return NPSNET_FUZZ_DATA_DIR; }
}  // namespace npsnet::dirs
