#pragma once
// What the robot's detector lets each segment of an image be, beyond its colours: a marking
// only when it is a stripe on the field (stripes.hpp, not above the field boundary), a boundary
// edge only along the field boundary (the gate, field_boundary.hpp). The review proposes
// through it, so a proposal names nothing the detector would drop but one thing: a painted line
// too thin to fill a pixel, which the detector's check refuses unless it is long and level
// (stripes.hpp: ThinLines), is paint to anyone looking and is proposed as a marking. Each class
// is trained on its candidates alone (fieldlines/train/review.hpp: LabelledCandidates), which
// leave such lines out.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/train/calibrate.hpp"

namespace fieldlines::studio {

// The stripes check's word on one segment; Unchecked where the robot would not check either (no
// field in view, not 8-bit BGR); ThinLine: no stripe to the robot's check, one with thin lines
// accepted (ThinLines::Accepted).
enum class StripeVerdict : std::uint8_t { NotStripe, Unchecked, ThinLine, Stripe };

struct ProposalGate {
  // Per segment, 1 = may be; both empty: nothing known (not detected here), nothing gated.
  std::vector<std::uint8_t> may_mark, may_bound;
  // Per segment, 1 = passed the stripes check (not merely unchecked); may be empty.
  std::vector<std::uint8_t> stripe;
  // Per segment, 1 = a thin line on the field (StripeVerdict::ThinLine): proposed as paint,
  // though may_mark is 0 (the detector drops it); may be empty.
  std::vector<std::uint8_t> thin_line;

  // `stripes`: per segment (DetectionResult::stripes; missing ones Unchecked); `boundary`
  // empty (no field in view): every segment may be either class.
  static ProposalGate of(std::span<const Segment> segments, const FieldBoundary& boundary,
                         std::span<const StripeVerdict> stripes);
  bool covers(std::size_t segments) const { return may_mark.size() == segments && may_bound.size() == segments; }
  // Whether segment i's proposal is None whatever its colours (neither class may be it, and it
  // is no thin line): the colour classes' margins say nothing about it.
  bool decided(std::size_t i) const {
    return i < may_mark.size() && i < may_bound.size() && !may_mark[i] && !may_bound[i] &&
           !(i < thin_line.size() && thin_line[i]);
  }
  // `proposed` for segment i, or None where the detector would drop it.
  Label apply(std::size_t i, Label proposed) const;
  // The proposal for segment i: classify() with `t`, gated; a thin line is a marking wherever a
  // stripe would be. A stripe the colour box misses is a marking still when its colours lean
  // towards the marking's transition rather than towards grey: its angle below the achromatic
  // angle (calibrate.hpp) by a margin. Paint seen as a stripe is rarely anything else, and a
  // box fitted on a few frames is narrower than the paint of all of them.
  Label propose(std::size_t i, const Segment& segment, const Thresholds& t) const;
};

// Label-free calibration of `segments` (`gates` parallel, or empty) from `start`: the marking
// class on its candidates (the stripes, as `fieldlines calibrate` fits it with the stripes stage
// on), the boundary class on every segment: along a boundary found in few frames, its edges
// are too few to tell from the grey ones (synthetic SSL frames: refused with, fitted without).
Calibration calibrate_gated(std::span<const Segment> segments, const Thresholds& start, const ProposalGate& gates);

}  // namespace fieldlines::studio
