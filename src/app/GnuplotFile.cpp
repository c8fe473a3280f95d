#include "app/GnuplotFile.h"

#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/Subprocess.h"

namespace tabletop {

std::string gnuplotQuoted(const std::string& s) {
  // A single-quoted gnuplot string undergoes no substitution (no `...`,
  // no @macro) and ends only at a quote, doubled here, or at the end of
  // the line: a control character, which could end the line and start a
  // command, is written as '?'.
  std::string out = "'";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\'') out += "''";
    else if (u < 0x20 || u == 0x7F) out += '?';
    else out += c;
  }
  return out + "'";
}

std::string plotNameProblem(const std::string& path) {
  if (!endsWith(path, ".png") && !endsWith(path, ".svg")) {
    return "expected a file name ending in .png or .svg, got '" + shownText(path) + "'";
  }
  return AtomicFile::destinationProblem(path);
}

std::string writeGnuplotFile(const std::string& path, const std::string& script, int width, int height) {
  if (const std::string problem = plotNameProblem(path); !problem.empty()) return problem;
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height) + " font 'sans,10'";
  const std::string terminal = (endsWith(path, ".png") ? "pngcairo" : "svg") + size;
  AtomicFile file(path);
  if (!file.problem().empty()) return file.problem();
  const std::string all = "set terminal " + terminal + "\nset output " + gnuplotQuoted(file.temporaryPath()) + "\n" +
                          script + "\nunset output\n";
  const int status = runProgram({"gnuplot"}, all, "");
  if (status == 127) return "plots need gnuplot (Debian package gnuplot-nox), which is not installed";
  if (status != 0) return "gnuplot failed to write '" + shownText(path) + "'";
  return file.commit();
}

}  // namespace tabletop
