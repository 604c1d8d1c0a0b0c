#include "fieldlines/train/review.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fieldlines/detect/enum_names.hpp"
#include "fieldlines/train/calibrate.hpp"

namespace fieldlines {
namespace {

constexpr double kProjectionUnit = 10, kAngleUnit = 2, kLengthUnit = 50;

// Signed distance of one class test to its boundary: >= 0 inside (the smallest slack), < 0
// outside (minus the distance to the nearest point inside: all violations must be undone).
double test_margin(const ClassFeatures& f, float length, const ClassThresholds& t) {
  const double slack[3] = {(f.projection - t.min_projection) / kProjectionUnit,
                           (t.max_angle_deg - f.angle_deg) / kAngleUnit, (length - t.min_length) / kLengthUnit};
  double inside = std::numeric_limits<double>::infinity(), outside = 0;
  for (const double s : slack) {
    inside = std::min(inside, s);
    if (s < 0) outside += s * s;
  }
  return inside >= 0 ? inside : -std::sqrt(outside);
}

}  // namespace

constexpr EnumNames<ProposalSource, 4> kSourceNames{{{{ProposalSource::LabelFree, "label-free"},
                                                     {ProposalSource::Trained, "trained"},
                                                     {ProposalSource::Start, "start"},
                                                     {ProposalSource::Disabled, "disabled"}}}};
std::string_view to_string(ProposalSource source) { return kSourceNames.name(source); }

ProposalThresholds proposal_thresholds(std::span<const Segment> all, std::span<const Segment> labelled,
                                       const Thresholds& start, const ProposalParams& params, std::stop_token stop) {
  return proposal_thresholds(calibrate(all, start), labelled, start, params, stop);
}

ProposalThresholds proposal_thresholds(const Calibration& fit, std::span<const Segment> labelled,
                                       const Thresholds& start, const ProposalParams& params, std::stop_token stop,
                                       const LabelledCandidates& candidates) {
  ProposalThresholds out;
  out.thresholds = start;
  // Only the spans parallel to the labels gate (feature_table.hpp: LabelledCandidates).
  const auto parallel = [&](std::span<const std::uint8_t> may) {
    return may.size() == labelled.size() ? may : std::span<const std::uint8_t>{};
  };
  const LabelledCandidates gates{parallel(candidates.marking), parallel(candidates.boundary)};
  for (const TrainClass cls : {TrainClass::Boundary, TrainClass::Marking}) {
    const bool boundary = cls == TrainClass::Boundary;
    const Label own = boundary ? Label::Boundary : Label::Marking;
    const std::span<const std::uint8_t> may = boundary ? gates.boundary : gates.marking;
    // A label counts towards training the class when the detector may call its segment that
    // class, or when it is one: a none the detector drops anyway says nothing about the box.
    std::size_t labels = 0, positives = 0;
    for (std::size_t i = 0; i < labelled.size(); ++i) {
      if (labelled[i].label == Label::Unlabelled) continue;
      const bool is_own = labelled[i].label == own;
      positives += is_own;
      labels += is_own || may.empty() || may[i] != 0;
    }
    ProposalSource& source = boundary ? out.boundary : out.marking;
    ClassThresholds& target = boundary ? out.thresholds.boundary.thresholds : out.thresholds.marking.thresholds;
    if (target == disabled_class()) {  // switched off: never proposed
      source = ProposalSource::Disabled;
      continue;
    }
    const ClassCalibration& c = boundary ? fit.boundary : fit.marking;
    const std::size_t enough = c.thresholds ? params.min_labels_to_train : params.min_labels_without_calibration;
    if (positives >= enough && labels - positives >= enough) {
      TrainParams p = params.train;
      p.target = cls;
      const TrainResult r = train(labelled, out.thresholds, p, {}, stop, gates);
      if (!r.cancelled) {
        target = boundary ? r.thresholds.boundary.thresholds : r.thresholds.marking.thresholds;
        source = ProposalSource::Trained;
        continue;
      }
    }
    if (c.thresholds) {
      target = *c.thresholds;
      source = ProposalSource::LabelFree;
      continue;
    }
    (boundary ? out.boundary_refused : out.marking_refused) = c.refused;
    if (!out.note.empty()) out.note += "; ";
    out.note += std::string(boundary ? "boundary" : "marking") + ": " + c.refused;
    // A field without a dark edge has no boundary: the defaults would mark shadows as one.
    if (boundary) {
      target = disabled_class();
      source = ProposalSource::Disabled;
    }
  }
  return out;
}

double decision_margin(const SegmentFeatures& f, const Thresholds& t) {
  const Label predicted = classify(f, t);
  const double b = test_margin(f.boundary, f.length, t.boundary.thresholds);
  double m = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < f.marking_count; ++i) m = std::max(m, test_margin(f.marking[i], f.length, t.marking.thresholds));
  // The boundary test comes first: a marking prediction also needs the boundary to fail.
  switch (predicted) {
    case Label::Boundary: return b;
    case Label::Marking: return std::min(m, -b);
    default: return std::min(-b, -m);
  }
}

}  // namespace fieldlines
