#include "gui/model/refusal_guidance.hpp"

namespace fieldlines::studio {

std::string refusal_guidance(const ProposalThresholds& made, const ProposalParams& params) {
  const std::string few = std::to_string(params.min_labels_without_calibration);
  std::string out;
  // Start: neither trained nor calibrated (review.hpp); the start thresholds propose little.
  if (made.marking == ProposalSource::Start && !made.marking_refused.empty()) {
    out = "Calibration cannot fit the markings: " + made.marking_refused + ". Label a few segments of each class (" +
          few + " markings and " + few + " others): the proposals then come from them.";
  }
  if (made.boundary == ProposalSource::Disabled && !made.boundary_refused.empty()) {
    if (!out.empty()) out += ' ';
    out += "Boundary off: " + made.boundary_refused + ". If the field has one, label " + few +
           " boundary segments: the proposals then come from them.";
  }
  return out;
}

}  // namespace fieldlines::studio
