#include "io/AtomicFile.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tabletop {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), temporary_(path_ + ".part") {}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temporary_.c_str());
}

std::string AtomicFile::commit() {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(temporary_, ec)) return path_ + ": nothing was written";
  std::filesystem::rename(temporary_, path_, ec);
  if (ec) return path_ + ": cannot rename into place: " + ec.message();
  committed_ = true;
  return "";
}

std::string AtomicFile::write(const std::string& path, const std::string& content) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporaryPath(), std::ios::binary | std::ios::trunc);
    if (!out) return path + ": cannot open for writing";
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) return path + ": cannot write (is the disk full?)";
  }
  return file.commit();
}

}  // namespace tabletop
