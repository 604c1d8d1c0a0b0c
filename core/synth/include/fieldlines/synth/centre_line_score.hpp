#pragma once
// The stripes' centre lines (field_features.hpp: Marking) against the truth's painted lines: what
// a robot takes from the stripes stage, one centre line per painted line, where the segment
// scores (gt_eval.hpp) count each of a line's two edges and a thin line's single edge segment
// may miss the other. A point counts when it lies within half the truth line's width there plus
// `margin_px` of the other's centre line (anywhere on the paint, give or take a pixel), the two
// running within max_angle_deg of each other:
//  - recall: the share of the truth's visible centre-line length (parts at least min_width_px
//    wide, as for the edges) near some detected centre line;
//  - precision: the share of the detected centre lines' length near some truth line's.
#include <span>

#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/synth/gt_eval.hpp"
#include "fieldlines/synth/truth.hpp"

namespace fieldlines::synth {

struct CentreLineScore {
  double truth_px = 0, covered_px = 0;    // visible truth centre-line length; of it, near a stripe
  double detected_px = 0, on_line_px = 0;  // the stripes' centre-line length; of it, on a line
  double recall() const { return truth_px > 0 ? covered_px / truth_px : 0.0; }
  double precision() const { return detected_px > 0 ? on_line_px / detected_px : 0.0; }
  CentreLineScore& operator+=(const CentreLineScore& o);
};

CentreLineScore score_centre_lines(const GroundTruth& truth, std::span<const Marking> markings,
                                   const GtMatchParams& params = {}, float margin_px = 1.0f);

}  // namespace fieldlines::synth
