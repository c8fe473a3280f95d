#pragma once

#include <functional>
#include <string>
#include <vector>

namespace tabletop {

/// Runs an external program (gnuplot, ffmpeg) by its argument vector, never
/// through a shell, so no text it is given can become a command: `input`
/// on its standard input (through an unnamed temporary file), standard
/// output and error into `logPath` (or /dev/null when empty). Returns its
/// exit status, 127 when it could not be started (not installed), or -1
/// when it was killed by a signal. `waiting`, when given, is called about
/// ten times a second while the program runs (a progress bar reads its
/// output then). `stop`, when given, is asked as often: once it says true
/// the program is ended (SIGTERM, then SIGKILL after a second) and
/// kStopped returned.
int runProgram(const std::vector<std::string>& args, const std::string& input, const std::string& logPath,
               const std::function<void()>& waiting = {}, const std::function<bool()>& stop = {});

/// What runProgram returns for a program that `stop` ended.
inline constexpr int kStopped = -2;

/// Whether `name` is an executable file in one of PATH's directories.
bool programAvailable(const std::string& name);

/// The last non-empty line of a text file ("" when there is none).
std::string lastLineOf(const std::string& path);

}  // namespace tabletop
