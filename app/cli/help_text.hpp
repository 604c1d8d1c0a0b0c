#pragma once
// Help lines built from tables (detector parameters, protocol values): a head in a left margin,
// its text wrapped at word boundaries, continuation lines indented two more columns.
#include <cstddef>
#include <string>
#include <string_view>

namespace fieldlines::cli {

// "  <head>   <text...>\n": the text starts at column `margin` (or three columns after a longer
// head) and its lines end before column `width` where a word boundary allows.
std::string help_row(std::string_view head, std::string_view text, std::size_t margin, std::size_t width = 100);

}  // namespace fieldlines::cli
