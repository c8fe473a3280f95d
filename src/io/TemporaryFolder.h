#pragma once

#include <string>

namespace tabletop {

/// A new private folder (mode 0700) under the system's temporary folder
/// (TMPDIR, else /tmp), removed with everything in it when the object goes:
/// where `render --video` puts frames nobody asked to keep.
class TemporaryFolder {
 public:
  /// Throws std::runtime_error when the folder cannot be made.
  explicit TemporaryFolder(const std::string& prefix);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace tabletop
