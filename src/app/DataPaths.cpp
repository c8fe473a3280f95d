#include "app/DataPaths.h"

#include <cstdlib>
#include <filesystem>

#include <LinearMath/btScalar.h>

namespace tabletop {

std::string dataRoot() {
  if (const char* dir = std::getenv("TABLETOP_DATA_DIR"); dir && *dir) return dir;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "tabletop";
    if (std::filesystem::is_directory(installed / "scenarios", ec)) return installed.string();
  }
  return TABLETOP_SOURCE_DIR;
}

std::string shippedScenarios() { return (std::filesystem::path(dataRoot()) / "scenarios").string(); }

std::string shippedFront() { return (std::filesystem::path(dataRoot()) / "data" / "tolerance_front.json").string(); }

std::string versionLine() {
  const int v = btGetVersion();
#ifdef BT_USE_DOUBLE_PRECISION
  const char* precision = "double precision";
#else
  const char* precision = "single precision";
#endif
  return std::string("tabletop ") + TABLETOP_VERSION + " (Bullet " + std::to_string(v / 100) + "." +
         std::to_string(v % 100) + ", " + precision + ")\ndata: " + dataRoot();
}

}  // namespace tabletop
