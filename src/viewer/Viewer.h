#pragma once

#include <iosfwd>
#include <string>

#include "viewer/ViewerSession.h"

namespace tabletop {

/// The window of `tabletop view`.
struct WindowSettings {
  int width = 1024;
  int height = 768;
  std::string screenshotDir = ".";  ///< where F12 writes its PNG files
};

/// The report's GLUT window (chapter 4) on freeglut: draws a
/// ViewerSession with the one GlRenderer, an overlay of its state, and maps
/// the keys, the mouse and the right-button menu onto it. Returns when the
/// window closes or on Q / Esc.
///
/// Returns kExitFailure (1) after one line on `err` when there is no
/// display to open (instead of dying inside glutInit).
int runViewer(ViewerSession& session, const WindowSettings& window, std::ostream& err);

/// Why no window can be opened here (no DISPLAY, or it cannot be opened),
/// or empty when one can.
std::string displayProblem();

/// The one line `tabletop view` prints when there is no display.
std::string noDisplayMessage(const std::string& problem);

}  // namespace tabletop
