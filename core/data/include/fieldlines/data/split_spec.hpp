#pragma once
// The parameters of the one seeded train/test split rule (fieldlines::split_train_test in
// fieldlines/train/splits.hpp). Here, below train, because a project file records them: the
// studio and `fieldlines train` then test on the same labelled segments. The defaults are the
// CLI's (`fieldlines train` without --split, --train-fraction, --seed).
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace fieldlines {

enum class SplitMode { ByImage, ByRow };

std::string_view to_string(SplitMode mode);
bool parse_split_mode(std::string_view text, SplitMode& out);  // "image" or "row"

struct SplitSpec {
  SplitMode mode = SplitMode::ByImage;  // by image: no image on both sides
  double train_fraction = 0.7;          // share of labelled images (rows) in train, (0, 1]
  std::uint64_t seed = 1;
  bool operator==(const SplitSpec&) const = default;
};

// {"mode": "image" | "row", "train_fraction": 0.7, "seed": 1}
nlohmann::json split_spec_to_json(const SplitSpec& spec);
// Missing fields keep their defaults; present ones must be valid (fraction in (0, 1], seed a
// non-negative integer). Throws fieldlines::Error naming `where` and the field.
SplitSpec split_spec_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace fieldlines
