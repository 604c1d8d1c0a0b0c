#pragma once
// The one way an enum gets its file and command-line names: a table of (value, name) pairs,
// looked up both ways, so a name is written once and parsing can never disagree with printing.
//
//   constexpr EnumNames<SplitMode, 2> kSplitNames{{{{SplitMode::ByImage, "image"}, {SplitMode::ByRow, "row"}}}};
//   kSplitNames.name(SplitMode::ByRow) == "row";   kSplitNames.parse("image", mode) == true
#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

namespace fieldlines {

template <class Enum, std::size_t N>
struct EnumNames {
  std::array<std::pair<Enum, std::string_view>, N> table;

  // "?" for a value missing from the table (a programming error, never user input).
  constexpr std::string_view name(Enum value) const {
    for (const auto& [v, n] : table)
      if (v == value) return n;
    return "?";
  }
  // False (and `out` untouched) when `text` is no name in the table.
  constexpr bool parse(std::string_view text, Enum& out) const {
    for (const auto& [v, n] : table)
      if (n == text) return out = v, true;
    return false;
  }
};

}  // namespace fieldlines
