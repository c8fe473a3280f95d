#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tabletop {

/// Measured results as plain rows, written by one writer per format: a
/// text table for the terminal, CSV and JSON for scripts. A column has a
/// key (its CSV heading and JSON name, with its unit: "cost_ms_per_s") and
/// a heading for the text table ("cost [ms/s]"); either may be empty to
/// keep the column out of that format. A cell holds the value written to
/// CSV and JSON and the text shown in the table.
struct ResultTable {
  struct Column {
    std::string key;      ///< CSV heading and JSON name; empty: text only
    std::string heading;  ///< text heading; empty: data only
  };
  struct Cell {
    nlohmann::json value;  ///< number, string or boolean
    std::string shown;     ///< as the text table shows it
  };

  std::string title;  ///< the text table's first line
  std::vector<Column> columns;
  std::vector<std::vector<Cell>> rows;  ///< one cell per column
  std::vector<std::string> notes;       ///< lines under the text table
};

/// A cell shown as the value itself (strings) or with `digits` decimals.
ResultTable::Cell cell(const std::string& text);
ResultTable::Cell cell(double value, int digits);
ResultTable::Cell cell(nlohmann::json value, std::string shown);

/// The title, the headings and the rows, each column as wide as its widest
/// entry, indented by two spaces; then the notes.
std::string toText(const ResultTable& table);

/// A heading row of keys and a row per result (RFC 4180 fields, numbers to
/// 17 significant digits, booleans as 1 and 0).
std::string toCsv(const ResultTable& table);

/// One value as a CSV field: numbers to 17 significant digits, booleans as
/// 1 and 0, null as nothing, strings and anything else quoted as needed.
std::string csvValue(const nlohmann::json& v);

/// An array of one object per row, keyed by the columns' keys.
nlohmann::json toJson(const ResultTable& table);

}  // namespace tabletop
