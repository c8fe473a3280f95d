#pragma once

#include <string>

namespace tabletop {

/// Draws a picture with gnuplot (Debian's gnuplot-nox) into `path`, whole
/// or not at all: `script` holds everything but the terminal and the
/// output, which are set here from the file's extension (.png or .svg).
/// Returns "" or what went wrong, in one line.
std::string writeGnuplotFile(const std::string& path, const std::string& script, int width, int height);

/// "" when the plot gnuplot wrote to `written` is whole (a PNG, when `png`,
/// ending in its IEND chunk, else an SVG in its closing tag), else what is
/// wrong.
std::string incompletePlot(const std::string& written, bool png);

/// "" when `path` can take a plot (ends in .png or .svg, and is not a
/// directory or a device), else why not: checked before anything runs.
std::string plotNameProblem(const std::string& path);

/// `s` as a gnuplot single-quoted string, which cannot carry a command.
std::string gnuplotQuoted(const std::string& s);

}  // namespace tabletop
