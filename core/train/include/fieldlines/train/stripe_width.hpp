#pragma once
// The widest plausible stripe for a venue, from its own markings (the third part of a label-free
// calibration, beside the detector's choice and the colour fit).
//
// The stripes stage takes paint up to `stripe_max_width` times the width scale of its row
// (stripes.hpp): wide enough by default for any league's near lines. What else is turf, white,
// turf (a goal's ground bar, a ball up close) is often wider than a venue's own lines; a limit
// from the venue's stripes keeps its lines and drops that. The limit is `margin` times the
// widest (as width_share) of the calibration frames' stripes that the fitted thresholds mark in
// the nearer half of their rows, never above the given one (wider paint was never measured).
// The widest rather than a percentile: an outlier raises the limit towards the given one, which
// costs the gain and no recall, while a low estimate cuts the venue's near lines (a percentile
// counts the many far pieces). The widest with company, though: a stripe wider than `margin`
// times every other is passed over (a person's leg on the turf, with one edge marked).
// Measured on the held-out venues: docs/calibration.md, "The widest stripe".
#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/train/calibration_inputs.hpp"

namespace fieldlines {

struct StripeWidthParams {
  double margin = 1.5;
  std::size_t min_stripes = 20;  // fewer measured stripes: the given limit is kept
};

struct MarkedStripe {
  double share;  // its width as width_share (stripes.hpp)
  double row;    // its row, px
};

// The rule above on the marked stripes: `given` when fewer than min_stripes.
double stripe_width_limit(const std::vector<MarkedStripe>& stripes, double given, const StripeWidthParams& params = {});

// The venue's stripe_max_width from `inputs` (with the stripe check on) and the thresholds fitted
// on them (calibrated_thresholds); `given` where fewer than min_stripes marked stripes were
// measured.
double calibrated_stripe_width(const CalibrationInputs& inputs, const Thresholds& fitted, double given,
                               const StripeWidthParams& params = {});

// What every face of calibration does with it: where the detector was chosen from the frames
// (`provenance`, detector_provenance's record, says "calibrated") and its stripes are on, sets
// detector.stripe_max_width to calibrated_stripe_width and records it in `provenance`; otherwise
// leaves both as they are (--keep-detector keeps the given limit).
void calibrate_stripe_width(DetectorParams& detector, nlohmann::json& provenance, const CalibrationInputs& inputs,
                            const Thresholds& fitted);

}  // namespace fieldlines
