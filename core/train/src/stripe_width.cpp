#include "fieldlines/train/stripe_width.hpp"

#include <algorithm>
#include <functional>
#include <vector>

#include "fieldlines/train/percentile.hpp"

namespace fieldlines {

double stripe_width_limit(const std::vector<MarkedStripe>& stripes, double given, const StripeWidthParams& params) {
  if (stripes.size() < params.min_stripes) return given;
  // The nearer half: there a line's width grows with its row as the limit's rule does. Towards
  // the horizon the rule's floor holds instead (a quarter of the height), and far lines' shares
  // say little of the near lines'.
  std::vector<double> rows;
  for (const MarkedStripe& s : stripes) rows.push_back(s.row);
  const double middle = median(std::move(rows));
  std::vector<double> near;
  for (const MarkedStripe& s : stripes)
    if (s.row >= middle) near.push_back(s.share);
  // The widest with company: a near line shows its width in more than one stripe (its other
  // edge, its pieces), so a stripe wider than `margin` times every other (a person's leg with one
  // edge marked) is none of the venue's lines.
  std::sort(near.begin(), near.end(), std::greater<>());
  for (std::size_t i = 0; i + 1 < near.size(); ++i)
    if (near[i] <= params.margin * near[i + 1]) return std::min(given, params.margin * near[i]);
  return given;
}

double calibrated_stripe_width(const CalibrationInputs& inputs, const Thresholds& fitted, double given,
                               const StripeWidthParams& params) {
  const std::vector<Segment>& segments = inputs.segments();
  const std::vector<float>& shares = inputs.width_shares();
  std::vector<MarkedStripe> marked;
  for (std::size_t i = 0; i < segments.size(); ++i)
    if (shares[i] > 0 && classify(segments[i], fitted) == Label::Marking)
      marked.push_back({shares[i], 0.5 * (segments[i].y0 + segments[i].y1)});
  return stripe_width_limit(marked, given, params);
}

void calibrate_stripe_width(DetectorParams& detector, nlohmann::json& provenance, const CalibrationInputs& inputs,
                            const Thresholds& fitted) {
  if (!provenance.value("calibrated", false) || !detector.stripes) return;
  detector.stripe_max_width = calibrated_stripe_width(inputs, fitted, detector.stripe_max_width);
  provenance["stripe_max_width"] = detector.stripe_max_width;
}

}  // namespace fieldlines
