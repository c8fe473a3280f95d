#include "sweep/SweepTable.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/ResultTable.h"

namespace tabletop {
namespace {

using nlohmann::json;

std::runtime_error failure(const std::string& path, const std::string& what) {
  return std::runtime_error(shownText(path, 256) + ": " + what);
}

int openTable(const std::string& path) {
  if (const std::string problem = AtomicFile::destinationProblem(path); !problem.empty()) throw failure(path, problem);
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw failure(path, std::string("cannot open for writing: ") + std::strerror(errno));
  return fd;
}

void writeAll(int fd, const std::string& text, const std::string& path) {
  std::size_t at = 0;
  while (at < text.size()) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw failure(path, std::string("cannot write: ") + std::strerror(errno));
    at += static_cast<std::size_t>(n);
  }
}

// The byte offsets just past each complete line (one ending in '\n').
std::vector<std::size_t> lineEnds(const std::string& path, std::vector<std::string>* lines) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::size_t> ends;
  std::string line;
  std::size_t offset = 0;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // no newline: a line cut off
    offset += line.size() + 1;
    ends.push_back(offset);
    if (lines) lines->push_back(line);
  }
  return ends;
}

void truncateTo(int fd, std::size_t size, const std::string& path) {
  if (::ftruncate(fd, static_cast<off_t>(size)) != 0 || ::lseek(fd, 0, SEEK_END) < 0) {
    throw failure(path, std::string("cannot truncate: ") + std::strerror(errno));
  }
}

}  // namespace

std::string csvHeading(const std::vector<std::string>& columns) {
  std::string s;
  for (const std::string& c : columns) s += (s.empty() ? "" : ",") + csvField(c);
  return s + "\n";
}

std::string csvLine(const SweepRow& row) {
  std::string s;
  for (std::size_t k = 0; k < row.size(); ++k) s += (k ? "," : "") + csvValue(row[k]);
  return s + "\n";
}

std::string jsonLine(const std::vector<std::string>& columns, const SweepRow& row) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < columns.size() && k < row.size(); ++k) j[columns[k]] = row[k];
  return j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

SweepTable::SweepTable(const std::string& prefix, const SweepSpec& spec)
    : prefix_(prefix), columns_(sweepColumns(spec)) {
  json_ = openTable(jsonPath());
  if (::flock(json_, LOCK_EX | LOCK_NB) != 0) {
    ::close(json_);
    throw failure(jsonPath(), "another sweep is writing this table");
  }
  try {
    resume(spec);
  } catch (...) {
    ::close(json_);
    if (csv_ >= 0) ::close(csv_);
    throw;
  }
}

void SweepTable::resume(const SweepSpec& spec) {
  csv_ = openTable(csvPath());
  // The CSV: its heading, then whole rows.
  std::vector<std::string> csvLines;
  std::vector<std::size_t> csvEnds = lineEnds(csvPath(), &csvLines);
  const std::string heading = csvHeading(columns_);
  if (csvLines.empty()) {
    truncateTo(csv_, 0, csvPath());
    writeAll(csv_, heading, csvPath());
    csvEnds = {heading.size()};
  } else if (csvLines.front() + "\n" != heading) {
    throw failure(csvPath(), "holds another sweep's table (other columns); give another --out");
  }
  // The JSON lines: each this spec's run, in order.
  std::vector<std::string> jsonLines;
  const std::vector<std::size_t> jsonEnds = lineEnds(jsonPath(), &jsonLines);
  std::size_t n = std::min(csvEnds.size() - 1, jsonEnds.size());
  const std::vector<std::string> names = spec.valueNames();
  for (std::size_t k = 0; k < n; ++k) {
    const json j = json::parse(jsonLines[k], nullptr, false);
    bool same = j.is_object() && j.value("run", json()) == json(k) && k < spec.runs();
    const std::vector<json> values = same ? spec.valuesOf(k) : std::vector<json>{};
    for (std::size_t p = 0; same && p < values.size(); ++p) same = j.value(names[p], json()) == values[p];
    if (!same) {
      throw failure(jsonPath() + ":" + std::to_string(k + 1), "holds another sweep's run " + std::to_string(k) +
                                                                   "; give another --out");
    }
  }
  done_ = n;
  truncateTo(csv_, csvEnds[n], csvPath());
  truncateTo(json_, n == 0 ? 0 : jsonEnds[n - 1], jsonPath());
}

SweepTable::~SweepTable() {
  if (csv_ >= 0) ::close(csv_);
  if (json_ >= 0) ::close(json_);
}

std::vector<SweepRow> SweepTable::rows() const {
  std::vector<std::string> lines;
  lineEnds(jsonPath(), &lines);
  std::vector<SweepRow> out;
  for (std::size_t k = 0; k < lines.size() && k < done_; ++k) {
    const json j = json::parse(lines[k], nullptr, false);
    SweepRow row;
    for (const std::string& c : columns_) row.push_back(j.is_object() ? j.value(c, json()) : json());
    out.push_back(std::move(row));
  }
  return out;
}

void SweepTable::append(const SweepRow& row) {
  // The JSON line first: a row counts once it is in both files.
  writeAll(json_, jsonLine(columns_, row), jsonPath());
  writeAll(csv_, csvLine(row), csvPath());
  ++done_;
}

}  // namespace tabletop
