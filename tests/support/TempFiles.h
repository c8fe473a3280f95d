#pragma once

// Where the tests write their files: a folder under the build tree
// (TABLETOP_TEST_TMPDIR, made when CMake configures), not the machine's
// /tmp, where every run of the suite left its files behind.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace tabletop::testing {

/// The folder, ending in '/'.
inline std::string tempDir() { return TABLETOP_TEST_TMPDIR; }

/// A folder for one test's files, `root` + `name` + "_" + the process id
/// (ctest runs the tests of one binary side by side). An earlier run's is
/// removed first, and this one with all it holds when the object goes, so
/// that runs do not pile folders up. It starts absent (for a command that
/// makes its own, such as render's --out-dir, or must refuse to) or empty.
class TempFolder {
 public:
  enum class Start { Absent, Empty };
  explicit TempFolder(const std::string& name, Start start = Start::Empty, const std::string& root = tempDir())
      : path_(root + name + "_" + std::to_string(getpid())) {
    std::filesystem::remove_all(path_);
    if (start == Start::Empty) std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace tabletop::testing
