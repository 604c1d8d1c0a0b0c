#include "fieldlines/train/stripe_width.hpp"

#include <algorithm>
#include <vector>

#include "fieldlines/train/percentile.hpp"

namespace fieldlines {

double calibrated_stripe_width(const CalibrationInputs& inputs, const Thresholds& fitted, double given,
                               const StripeWidthParams& params) {
  const std::vector<Segment>& segments = inputs.segments();
  const std::vector<float>& shares = inputs.width_shares();
  struct Stripe {
    double share, row;
  };
  std::vector<Stripe> marked;
  std::vector<double> rows;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (shares[i] > 0 && classify(segments[i], fitted) == Label::Marking) {
      marked.push_back({shares[i], 0.5 * (segments[i].y0 + segments[i].y1)});
      rows.push_back(marked.back().row);
    }
  }
  if (marked.size() < params.min_stripes) return given;
  // The nearer half: there a line's width grows with its row as the limit's rule does. Towards
  // the horizon the rule's floor holds instead (a quarter of the height), and far lines' shares
  // say little of the near lines'.
  const double middle = median(std::move(rows));
  double widest = 0;
  for (const Stripe& s : marked)
    if (s.row >= middle) widest = std::max(widest, s.share);
  return std::min(given, params.margin * widest);
}

void calibrate_stripe_width(DetectorParams& detector, nlohmann::json& provenance, const CalibrationInputs& inputs,
                            const Thresholds& fitted) {
  if (!provenance.value("calibrated", false) || !detector.stripes) return;
  detector.stripe_max_width = calibrated_stripe_width(inputs, fitted, detector.stripe_max_width);
  provenance["stripe_max_width"] = detector.stripe_max_width;
}

}  // namespace fieldlines
