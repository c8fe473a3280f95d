#pragma once

#include <memory>
#include <regex>
#include <string>

#include <CLI/CLI.hpp>

namespace tabletop {

/// --help in words: an option's value as NUMBER, INTEGER, TEXT or its
/// choices, with its range as "from A to B", instead of CLI11's internal
/// forms ("FLOAT:NUMBER from ...", "INT:INT in [1 - 10000]"), and a
/// negative flag without its "{false}". Installed on the program before
/// its commands are added, which inherit it.
class PlainHelp : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* opt, bool positional) const override {
    std::string name = CLI::Formatter::make_option_name(opt, positional);
    return std::regex_replace(name, std::regex("\\{[^}]*\\}"), "");
  }

  std::string make_option_opts(const CLI::Option* opt) const override {
    std::string opts = CLI::Formatter::make_option_opts(opt);
    const std::string type = opt->get_type_name();
    if (opt->get_type_size() != 0 && !type.empty() && opt->get_option_text().empty()) {
      const std::size_t at = opts.find(type);
      if (at != std::string::npos) opts.replace(at, type.size(), plain(type));
    }
    return opts;
  }

  /// CLI11's type name `type` in words.
  static std::string plain(const std::string& type) {
    const std::size_t colon = type.find(':');
    const std::string base = type.substr(0, colon);
    const std::string rest = colon == std::string::npos ? "" : type.substr(colon + 1);
    std::smatch m;
    if (std::regex_match(rest, m, std::regex("NUMBER from (\\S+) to (\\S+)"))) {
      return "NUMBER from " + m[1].str() + " to " + m[2].str();
    }
    if (std::regex_match(rest, m, std::regex("INT in \\[(\\S+) - (\\S+)\\]"))) {
      return "INTEGER from " + m[1].str() + " to " + m[2].str();
    }
    if (rest == "POSITIVE") return "NUMBER > 0";
    if (!rest.empty()) return rest;
    if (base == "FLOAT") return "NUMBER";
    if (base == "INT" || base == "UINT") return "INTEGER";
    return base;
  }
};

}  // namespace tabletop
