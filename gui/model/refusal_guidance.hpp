#pragma once
// When calibration refuses a class and the labels do not cover it yet, the review loop has
// little to propose (on a venue whose paint calibration cannot tell from grey edges, every field
// line comes out as none). The one line the status bar and the Train tab show then: why, in
// calibration's words, and what to do next.
#include <string>

#include "fieldlines/train/review.hpp"

namespace fieldlines::studio {

// Empty when every class came from labels or calibration (or was switched off by the user).
std::string refusal_guidance(const ProposalThresholds& made, const ProposalParams& params);

}  // namespace fieldlines::studio
