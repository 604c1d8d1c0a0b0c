#include "app/cli/detector_params_help.hpp"

#include <cstdio>

#include "app/cli/help_text.hpp"
#include "fieldlines/detect/detector_params.hpp"

namespace fieldlines::cli {

std::string detector_params_help() {
  std::string text =
      "detector parameters (the \"detector\" object of a --thresholds file; a missing key keeps its default):\n";
  // Columns: name, default, range, unit; the meaning wraps in the last one.
  char head[96];
  const auto row = [&](std::string_view name, const std::string& fallback, const std::string& range,
                       std::string_view unit, std::string_view meaning) {
    std::snprintf(head, sizeof head, "%-21.*s %-8s %-12s %.*s", static_cast<int>(name.size()), name.data(),
                  fallback.c_str(), range.c_str(), static_cast<int>(unit.size()), unit.data());
    text += help_row(head, meaning, 52);
  };
  row("name", "default", "range", "unit", "meaning");
  for (const ParamSpec& spec : kDetectorParamSpecs) {
    if (!spec.in_files) continue;
    const bool flag = std::holds_alternative<bool DetectorParams::*>(spec.member);
    row(spec.name, param_default_text(spec), flag ? "true|false" : spec.range.to_string(), spec.unit, spec.help);
  }
  return text;
}

}  // namespace fieldlines::cli
