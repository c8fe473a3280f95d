#include "app/GnuplotFile.h"

#include <sys/wait.h>

#include <cstdio>

#include "io/AtomicFile.h"

namespace tabletop {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string gnuplotQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string writeGnuplotFile(const std::string& path, const std::string& script, int width, int height) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height) + " font 'sans,10'";
  std::string terminal;
  if (endsWith(path, ".png")) {
    terminal = "pngcairo" + size;
  } else if (endsWith(path, ".svg")) {
    terminal = "svg" + size;
  } else {
    return "expected a file name ending in .png or .svg, got '" + path + "'";
  }
  AtomicFile file(path);
  const std::string all = "set terminal " + terminal + "\nset output " + gnuplotQuoted(file.temporaryPath()) + "\n" +
                          script + "\nunset output\n";
  // gnuplot falls back to standard output when it cannot open a file.
  FILE* pipe = popen("gnuplot >/dev/null 2>&1", "w");
  if (!pipe) return "could not start gnuplot";
  std::fwrite(all.data(), 1, all.size(), pipe);
  const int status = pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) == 127) {
    return "plots need gnuplot (Debian package gnuplot-nox), which is not installed";
  }
  if (WEXITSTATUS(status) != 0) return "gnuplot failed to write '" + path + "'";
  return file.commit();
}

}  // namespace tabletop
