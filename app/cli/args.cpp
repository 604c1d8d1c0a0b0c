#include "app/cli/args.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::cli {

ParsedArgs::ParsedArgs(const std::vector<std::string>& args, std::set<std::string> value_options,
                       std::set<std::string> flag_options) {
  bool only_positionals = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (only_positionals || a.size() < 2 || a[0] != '-' || a == "-") {
      positionals_.push_back(a);
      continue;
    }
    if (a == "--") {
      only_positionals = true;
      continue;
    }
    std::string name = a;
    std::optional<std::string> inline_value;
    if (const auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
      name = a.substr(0, eq);
      inline_value = a.substr(eq + 1);
    }
    if (value_options.count(name)) {
      if (inline_value) {
        values_[name] = *inline_value;
      } else if (i + 1 < args.size()) {
        values_[name] = args[++i];
      } else {
        throw Error(name + " needs a value");
      }
    } else if (flag_options.count(name) && !inline_value) {
      flags_.insert(name);
    } else {
      throw Error("unknown option '" + a + "' (see --help)");
    }
  }
}

std::optional<std::string> ParsedArgs::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::string ParsedArgs::value_or(const std::string& name, const std::string& fallback) const {
  return value(name).value_or(fallback);
}

int ParsedArgs::int_or(const std::string& name, int fallback, int min, int max) const {
  const auto v = value(name);
  return v ? parse_int(*v, name, min, max) : fallback;
}

double ParsedArgs::double_or(const std::string& name, double fallback, double min, double max) const {
  const auto v = value(name);
  return v ? parse_double(*v, name, min, max) : fallback;
}

int parse_int(std::string_view text, std::string_view what, int min, int max) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max)
    throw Error(std::string(what) + ": expected a whole number in [" + std::to_string(min) + ", " +
                std::to_string(max) + "], got '" + std::string(text) + "'");
  return value;
}

double parse_double(std::string_view text, std::string_view what, double min, double max) {
  const std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(value) || value < min || value > max)
    throw Error(std::string(what) + ": expected a number in [" + std::to_string(min) + ", " +
                std::to_string(max) + "], got '" + s + "'");
  return value;
}

std::pair<double, double> parse_interval(std::string_view text, std::string_view what, double min, double max) {
  const auto colon = text.find(':');
  if (colon == std::string_view::npos)
    throw Error(std::string(what) + ": expected LO:HI, got '" + std::string(text) + "'");
  const double lo = parse_double(text.substr(0, colon), what, min, max);
  const double hi = parse_double(text.substr(colon + 1), what, min, max);
  if (lo > hi) throw Error(std::string(what) + ": LO must not exceed HI, got '" + std::string(text) + "'");
  return {lo, hi};
}

}  // namespace fieldlines::cli
