#include "fieldlines/detect/detector_params.hpp"

#include <cmath>
#include <cstdio>
#include <type_traits>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

std::string format_param_number(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

std::string ParamRange::to_string() const {
  std::string text(1, lo_open ? '(' : '[');
  text += format_param_number(lo);
  text += ", ";
  text += format_param_number(hi);
  text += ']';
  return text;
}

const ParamSpec* find_param_spec(std::string_view name) {
  for (const ParamSpec& s : kDetectorParamSpecs)
    if (s.name == name) return &s;
  return nullptr;
}

std::optional<std::string> param_error(const ParamSpec& spec, double value) {
  if (spec.range.empty()) return std::nullopt;
  if (!spec.range.contains(value))
    return format_param_number(value) + " is outside " + spec.range.to_string();
  if (spec.odd && value >= 3 && std::fmod(value, 2) == 0)
    return format_param_number(value) + " is even; expected an odd size (or below 3 for none)";
  return std::nullopt;
}

std::string param_default_text(const ParamSpec& spec) {
  const DetectorParams defaults;
  return std::visit(
      [&](auto member) -> std::string {
        const auto& v = defaults.*member;
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::vector<int>>) {
          std::string text;
          for (const int e : v) text += (text.empty() ? "" : ", ") + std::to_string(e);
          return text;
        } else {
          return format_param_number(static_cast<double>(v));
        }
      },
      spec.member);
}

void validate(const DetectorParams& p) {
  for (const ParamSpec& spec : kDetectorParamSpecs) {
    const auto fail = [&](const std::string& field, const std::string& why) {
      throw Error("detector parameter " + field + ": " + why);
    };
    std::visit(
        [&](auto member) {
          const auto& v = p.*member;
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::vector<int>>) {
            for (std::size_t i = 0; i < v.size(); ++i)
              if (auto why = param_error(spec, v[i])) fail(std::string(spec.name) + "[" + std::to_string(i) + "]", *why);
          } else if constexpr (!std::is_same_v<T, bool>) {
            if (auto why = param_error(spec, static_cast<double>(v))) fail(std::string(spec.name), *why);
          }
        },
        spec.member);
  }
}

}  // namespace fieldlines
