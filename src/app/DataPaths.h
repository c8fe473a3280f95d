#pragma once

#include <string>

namespace tabletop {

/// Where tabletop's own files are (the shipped scenarios and the tolerance
/// front), found from the program, never from the current folder: the
/// folder TABLETOP_DATA_DIR names if set; else, for an installed program,
/// PREFIX/share/tabletop beside its bin/; else the source tree it was built
/// from (dataFolder, scenario/ShippedScenes.h). Each holds scenarios/ and
/// data/.
std::string dataRoot();

/// dataRoot()/scenarios, where the shipped scenes are found by name.
std::string shippedScenarios();

/// dataRoot()/data/tolerance_front.json, which run --tolerance reads.
std::string shippedFront();

/// "tabletop 0.1.0 (Bullet 3.24, double precision)", then on a line of its
/// own "data: " and dataRoot(), the folder the program reads its files from.
std::string versionLine();

}  // namespace tabletop
