#pragma once

// Where the tests write their files: a folder under the build tree
// (TABLETOP_TEST_TMPDIR, made when CMake configures), not the machine's
// /tmp, where every run of the suite left its files behind.

#include <string>

namespace tabletop::testing {

/// The folder, ending in '/'.
inline std::string tempDir() { return TABLETOP_TEST_TMPDIR; }

}  // namespace tabletop::testing
