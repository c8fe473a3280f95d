#pragma once

#include <string>

namespace tabletop {

/// An advisory lock (flock) on a folder, held while the object lives, so
/// two programs writing into one folder (two renders) do not mix their
/// files. Taken without waiting: held() says whether it was.
class FolderLock {
 public:
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  bool held() const { return held_; }

 private:
  int fd_;
  bool held_ = false;
};

}  // namespace tabletop
