#pragma once
// What a labelling review loop asks of training: thresholds to propose labels from, and how
// close each segment's prediction is to flipping (to review the uncertain ones first).
//
// Proposals come from label-free calibration while the project has too few labels of a class
// to train it, and from supervised training on the labels so far afterwards, class by class.
// A class calibration refuses is trained from a few labels: there is nothing better to wait for.
// A class switched off (its start thresholds are disabled_class(), fieldlines/train/calibrate.hpp)
// stays off, and so does a boundary calibration refuses (as `fieldlines calibrate` writes it).
#include <cstdint>
#include <span>
#include <stop_token>
#include <string>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/training.hpp"

namespace fieldlines {

enum class ProposalSource { LabelFree, Trained, Start, Disabled };
std::string_view to_string(ProposalSource source);  // "label-free", "trained", "start", "disabled"

struct ProposalThresholds {
  Thresholds thresholds;
  ProposalSource marking = ProposalSource::Start, boundary = ProposalSource::Start;
  std::string note;  // one line for a status bar, e.g. why calibration was not used
  // Calibration's reason for a class that came neither from labels nor from calibration
  // (source Start or, for a refused boundary, Disabled); empty otherwise.
  std::string marking_refused, boundary_refused;
};

struct ProposalParams {
  // A class is trained once this many of its segments are labelled (and as many of others).
  std::size_t min_labels_to_train = 10;
  // The same where calibration refuses the class: a few labels beat no proposal at all.
  std::size_t min_labels_without_calibration = 3;
  TrainParams train;  // target is set per class
};

// `all`: every segment of the project (labels ignored); `labelled`: the human labels so far.
// `fit`: calibrate(all, start), for callers that propose from several label sets over the same
// segments (calibration never reads labels, so one fit serves them all).
ProposalThresholds proposal_thresholds(const Calibration& fit, std::span<const Segment> labelled,
                                       const Thresholds& start, const ProposalParams& params = {},
                                       std::stop_token stop = {}, const LabelledCandidates& candidates = {});
// A marking class that can be neither trained nor calibrated keeps `start`'s thresholds; such a
// boundary class is disabled. Never throws on
// a lack of data; throws fieldlines::Error only for invalid `params`.
ProposalThresholds proposal_thresholds(std::span<const Segment> all, std::span<const Segment> labelled,
                                       const Thresholds& start, const ProposalParams& params = {},
                                       std::stop_token stop = {});

// How far a segment's prediction is from changing, in threshold units (projection / 10,
// degrees / 2, saliency / 50: a step of each is about as meaningful): the smallest move of one
// threshold set's boundary that would change the predicted label. 0 = on a boundary.
double decision_margin(const SegmentFeatures& features, const Thresholds& thresholds);

}  // namespace fieldlines
