#pragma once
// Text cut to a width with "..." at its end, for one-line places (the status bar) where a wrap
// has no room; the panel shows the full text on hover. Window-free: the caller measures.
#include <functional>
#include <string>
#include <string_view>

namespace fieldlines::studio {

inline constexpr std::string_view kEllipsis = "...";

// `text` when measure(text) <= width; else its longest prefix of whole UTF-8 characters that,
// followed by kEllipsis, measures at most `width` (kEllipsis alone, or empty, when even that
// does not fit). `measure` must grow with the text (a font's width does).
std::string ellipsize(std::string_view text, float width, const std::function<float(std::string_view)>& measure);

}  // namespace fieldlines::studio
