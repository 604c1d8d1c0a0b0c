#include "fieldlines/data/split_spec.hpp"

#include "fieldlines/detect/enum_names.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines {

// Namespace-scope constexpr: internal linkage.
constexpr EnumNames<SplitMode, 2> kNames{{{{SplitMode::ByImage, "image"}, {SplitMode::ByRow, "row"}}}};

std::string_view to_string(SplitMode mode) { return kNames.name(mode); }
bool parse_split_mode(std::string_view text, SplitMode& out) { return kNames.parse(text, out); }

nlohmann::json split_spec_to_json(const SplitSpec& spec) {
  return {{"mode", to_string(spec.mode)}, {"train_fraction", spec.train_fraction}, {"seed", spec.seed}};
}

SplitSpec split_spec_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw Error(where + ": expected an object");
  SplitSpec spec;
  if (const auto m = j.find("mode"); m != j.end()) {
    if (!m->is_string() || !parse_split_mode(m->get<std::string>(), spec.mode))
      throw Error(where + ".mode: expected \"image\" or \"row\"");
  }
  if (const auto f = j.find("train_fraction"); f != j.end()) {
    if (!f->is_number() || !(f->get<double>() > 0.0 && f->get<double>() <= 1.0))
      throw Error(where + ".train_fraction: expected a number in (0, 1]");
    spec.train_fraction = f->get<double>();
  }
  if (const auto s = j.find("seed"); s != j.end()) {
    if (!s->is_number_unsigned()) throw Error(where + ".seed: expected a non-negative integer");
    spec.seed = s->get<std::uint64_t>();
  }
  return spec;
}

}  // namespace fieldlines
