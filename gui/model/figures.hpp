#pragma once
// Precision, recall and F1 as the panels show them. A class with no data in a split (no
// labelled and no predicted segment: always so in an empty test split) shows "n/a": core's 0 for
// 0/0 would read as a score.
#include <string>

#include "fieldlines/train/metrics.hpp"

namespace fieldlines::studio {

// `value` (one of c's figures) with three decimals, or "n/a" when c.empty() (the CLI's rule too).
std::string format_figure(const ClassCounts& c, double value);

}  // namespace fieldlines::studio
