// fuzz_support.hpp's folders, from the generated npsnet_dirs.hpp: the only object of a fuzz
// target or replay that depends on the checkout's folder (ccache, scripts/ccache.sh).
#include "fuzz_support.hpp"

#include "npsnet_dirs.hpp"

namespace npsnet::fuzz {
std::filesystem::path data_dir() { return NPSNET_FUZZ_DATA_DIR; }
std::filesystem::path source_dir() { return NPSNET_SOURCE_DIR; }
}  // namespace npsnet::fuzz
