#include "io/ResultTable.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/Text.h"

namespace tabletop {

ResultTable::Cell cell(const std::string& text) { return {text, text}; }

ResultTable::Cell cell(double value, int digits) { return {value, fixed(value, digits)}; }

ResultTable::Cell cell(nlohmann::json value, std::string shown) { return {std::move(value), std::move(shown)}; }

std::string toText(const ResultTable& table) {
  std::vector<std::size_t> width(table.columns.size(), 0);
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    width[c] = table.columns[c].heading.size();
    for (const auto& row : table.rows) width[c] = std::max(width[c], row[c].shown.size());
  }
  std::ostringstream o;
  const auto line = [&](const auto& text) {
    std::string s = "  ";
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (!table.columns[c].heading.empty()) s += padded(text(c), width[c] + 1);
    }
    s.erase(s.find_last_not_of(' ') + 1);
    o << s << "\n";
  };
  if (!table.title.empty()) o << table.title << "\n";
  line([&](std::size_t c) { return table.columns[c].heading; });
  for (const auto& row : table.rows) line([&](std::size_t c) { return row[c].shown; });
  for (const std::string& note : table.notes) o << "  " << note << "\n";
  return o.str();
}

std::string csvValue(const nlohmann::json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_string()) return csvField(v.get<std::string>());
  if (v.is_number_float()) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v.get<double>());
    return text;
  }
  return v.is_null() ? "" : csvField(v.dump());
}

std::string toCsv(const ResultTable& table) {
  std::ostringstream o;
  std::string sep;
  for (const auto& column : table.columns) {
    if (column.key.empty()) continue;
    o << sep << column.key;
    sep = ",";
  }
  o << "\n";
  for (const auto& row : table.rows) {
    sep.clear();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (table.columns[c].key.empty()) continue;
      o << sep << csvValue(row[c].value);
      sep = ",";
    }
    o << "\n";
  }
  return o.str();
}

nlohmann::json toJson(const ResultTable& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : table.rows) {
    nlohmann::json object = nlohmann::json::object();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (!table.columns[c].key.empty()) object[table.columns[c].key] = row[c].value;
    }
    rows.push_back(std::move(object));
  }
  return rows;
}

}  // namespace tabletop
