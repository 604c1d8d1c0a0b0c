#include "gui/model/proposal_gate.hpp"

#include <algorithm>
#include <cmath>

namespace fieldlines::studio {
namespace {

// How far below the achromatic angle a stripe's colours must stay to be proposed a marking.
constexpr double kStripeAngleMarginDeg = 1.0;

}  // namespace

ProposalGate ProposalGate::of(std::span<const Segment> segments, const FieldBoundary& boundary,
                              std::span<const StripeVerdict> stripes) {
  ProposalGate gate;
  gate.may_mark.resize(segments.size());
  gate.may_bound.resize(segments.size());
  gate.stripe.resize(segments.size());
  gate.thin_line.resize(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const BoundaryPlace place = place_of(segments[i], boundary);  // Below when there is no boundary
    const StripeVerdict verdict = i < stripes.size() ? stripes[i] : StripeVerdict::Unchecked;
    const bool on_field = place != BoundaryPlace::Above;
    gate.may_mark[i] = (verdict == StripeVerdict::Stripe || verdict == StripeVerdict::Unchecked) && on_field;
    gate.stripe[i] = verdict == StripeVerdict::Stripe && on_field;
    gate.thin_line[i] = verdict == StripeVerdict::ThinLine && on_field;
    gate.may_bound[i] = boundary.empty() || place == BoundaryPlace::Along;
  }
  return gate;
}

Label ProposalGate::apply(std::size_t i, Label proposed) const {
  if (i >= may_mark.size() || i >= may_bound.size()) return proposed;
  if (proposed == Label::Marking && !may_mark[i]) return Label::None;
  if (proposed == Label::Boundary && !may_bound[i]) return Label::None;
  return proposed;
}

Label ProposalGate::propose(std::size_t i, const Segment& segment, const Thresholds& t) const {
  const Label colour = classify(segment, t);
  const bool thin = i < thin_line.size() && thin_line[i];
  if (thin && colour == Label::Marking) return Label::Marking;  // apply() would drop it
  const bool paint = thin || (i < stripe.size() && stripe[i]);
  if (colour != Label::None || !paint) return apply(i, colour);
  if (t.marking.thresholds == disabled_class()) return Label::None;  // switched off stays off
  Thresholds widened = t;
  float& max_angle = widened.marking.thresholds.max_angle_deg;
  max_angle = std::max(max_angle, static_cast<float>(achromatic_angle_deg(t.marking) - kStripeAngleMarginDeg));
  return classify(segment, widened) == Label::Marking ? Label::Marking : Label::None;
}

Calibration calibrate_gated(std::span<const Segment> segments, const Thresholds& start, const ProposalGate& gates) {
  const bool known = gates.may_mark.size() == segments.size();
  return calibrate(segments, start, {}, {}, known ? std::span<const std::uint8_t>(gates.may_mark) : std::span<const std::uint8_t>{});
}

}  // namespace fieldlines::studio
