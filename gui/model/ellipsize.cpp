#include "gui/model/ellipsize.hpp"

#include <vector>

namespace fieldlines::studio {

std::string ellipsize(std::string_view text, float width, const std::function<float(std::string_view)>& measure) {
  if (measure(text) <= width) return std::string(text);
  if (measure(kEllipsis) > width) return {};
  // Cut points between whole characters: never inside a UTF-8 sequence (continuation bytes 10xxxxxx).
  std::vector<std::size_t> cuts;
  for (std::size_t i = 0; i < text.size(); ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) cuts.push_back(i);
  const auto fits = [&](std::size_t n) { return measure(std::string(text.substr(0, n)) + std::string(kEllipsis)) <= width; };
  // Binary search for the last cut that fits; cuts[0] == 0 always fits (the ellipsis alone does).
  std::size_t lo = 0, hi = cuts.size();
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (fits(cuts[mid]) ? lo : hi) = mid;
  }
  std::string out(text.substr(0, cuts[lo]));
  while (!out.empty() && out.back() == ' ') out.pop_back();  // "word ..." reads as a cut, "word..." too
  return out + std::string(kEllipsis);
}

}  // namespace fieldlines::studio
