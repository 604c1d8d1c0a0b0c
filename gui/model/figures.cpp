#include "gui/model/figures.hpp"

#include <cstdio>

namespace fieldlines::studio {

std::string format_figure(const ClassCounts& c, double value) {
  if (c.empty()) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

}  // namespace fieldlines::studio
