// test_util.hpp's folders: the only test_net object given their paths (net/CMakeLists.txt sets
// them on this file alone), so the others do not depend on the checkout's folder (ccache).
#include "test_util.hpp"

namespace nettest {
std::filesystem::path captures_dir() { return std::filesystem::path(NET_TEST_DATA_DIR) / "captures"; }
std::string js_dir() { return NET_TEST_JS_DIR; }
std::string binary_dir() { return NET_TEST_BINARY_DIR; }
}  // namespace nettest
