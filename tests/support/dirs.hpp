// Where this checkout and its build lie, for the tests, benchmarks and fuzz targets (their data
// files, the node binary they start). Defined once, in support/dirs.cpp (library npsnet_test_dirs),
// from the generated npsnet_dirs.hpp: no other test, benchmark or fuzz object depends on the
// clone's folder, so ccache reuses them from a clone in any folder (scripts/ccache.sh).
#pragma once

namespace npsnet::dirs {
const char* source();     // the checkout (CMake's PROJECT_SOURCE_DIR)
const char* binary();     // the build tree (PROJECT_BINARY_DIR): npsnet, tools/
const char* fuzz_data();  // fuzz/data: the fuzz targets' small world
}  // namespace npsnet::dirs
