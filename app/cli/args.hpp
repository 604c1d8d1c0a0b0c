#pragma once
// A small, strict command-line parser: unknown options are errors, values are checked.
#include <map>
#include <optional>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fieldlines::cli {

class ParsedArgs {
 public:
  // `value_options` take a value (--name V or --name=V); `flag_options` do not.
  // Throws fieldlines::Error on an unknown option or a missing value.
  ParsedArgs(const std::vector<std::string>& args, std::set<std::string> value_options,
             std::set<std::string> flag_options);

  bool flag(const std::string& name) const { return flags_.count(name) != 0; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::optional<std::string> value(const std::string& name) const;
  std::string value_or(const std::string& name, const std::string& fallback) const;
  // Parse a number; throw fieldlines::Error "--name: expected ... got '...'" when malformed.
  int int_or(const std::string& name, int fallback, int min, int max) const;
  double double_or(const std::string& name, double fallback, double min, double max) const;
  const std::vector<std::string>& positionals() const { return positionals_; }

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
  std::vector<std::string> positionals_;
};

int parse_int(std::string_view text, std::string_view what, int min, int max);
double parse_double(std::string_view text, std::string_view what, double min, double max);
// "LO:HI" with min <= LO <= HI <= max.
std::pair<double, double> parse_interval(std::string_view text, std::string_view what, double min, double max);

}  // namespace fieldlines::cli
