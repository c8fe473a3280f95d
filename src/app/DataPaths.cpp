#include "app/DataPaths.h"

#include <filesystem>

#include <LinearMath/btScalar.h>

#include "scenario/ShippedScenes.h"

namespace tabletop {

std::string dataRoot() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string installed = ec ? "" : (exe.parent_path().parent_path() / "share" / "tabletop").string();
  return dataFolder(installed, TABLETOP_SOURCE_DIR);
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
