#include "app/GnuplotFile.h"

#include <cstdio>
#include <fstream>
#include <iterator>

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

std::string incompletePlot(const std::string& written, bool png) {
  std::ifstream in(written, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && in.fail()) return "cannot read what it wrote";
  if (png) {
    // A PNG starts with its signature and ends with the IEND chunk.
    static const std::string signature("\x89PNG\r\n\x1a\n", 8);
    static const std::string end("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
    if (text.compare(0, signature.size(), signature) != 0 || !endsWith(text, end)) {
      return "the PNG it wrote is incomplete (" + std::to_string(text.size()) + " bytes)";
    }
    return "";
  }
  const std::size_t close = text.rfind("</svg>");
  if (close == std::string::npos || text.find_first_not_of(" \t\r\n", close + 6) != std::string::npos) {
    return "the SVG it wrote is incomplete (" + std::to_string(text.size()) + " bytes)";
  }
  return "";
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
  // gnuplot's messages, to say why it failed.
  const std::string log = file.temporaryPath() + ".log";
  const int status = runProgram({"gnuplot"}, all, log);
  const std::string why = lastLineOf(log);
  std::remove(log.c_str());
  if (status == 127) return "plots need gnuplot (Debian package gnuplot-nox), which is not installed";
  const std::string failed = "gnuplot failed to write '" + shownText(path) + "'";
  if (status != 0) return failed + (why.empty() ? std::string() : ": " + shownText(why, 200));
  // gnuplot exits 0 even when its writes failed (a full disk, a file size
  // limit): the plot is kept only if it is whole.
  if (const std::string wrong = incompletePlot(file.temporaryPath(), endsWith(path, ".png")); !wrong.empty()) {
    return failed + ": " + wrong + (why.empty() ? std::string() : " (" + shownText(why, 200) + ")");
  }
  return file.commit();
}

}  // namespace tabletop
