// The studio's review loop: propose labels, accept an image's proposals with one key, and
// visit the least certain segments first. Part of StudioController, in its own file because
// it is one concept: what a person reviews next.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "fieldlines/train/protocols.hpp"
#include "fieldlines/train/review.hpp"
#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

ProposalParams StudioController::proposal_params() {
  ProposalParams params;
  // Trained like `fieldlines train` trains by default, so proposals match what the CLI would make.
  params.train = protocol_spec(Protocol::Ours).train;
  return params;
}

std::size_t StudioController::refresh_proposals(const Thresholds& t) {
  std::size_t proposed = 0;
  for (std::size_t img = 0; img < image_count(); ++img) {
    ImageEntry& e = project_.images[img];
    const ProposalGate& gate = detection_.gate(img);
    e.proposals.resize(e.segments.size(), Label::Unlabelled);
    for (std::size_t i = 0; i < e.segments.size(); ++i) {
      const bool open = e.segments[i].label == Label::Unlabelled;
      e.proposals[i] = open ? gate.propose(i, e.segments[i], t) : Label::Unlabelled;
      proposed += open;
    }
  }
  proposal_thresholds_ = t;
  return proposed;
}

std::string StudioController::propose() {
  const LabelledSet labelled = project_.labelled();
  const Thresholds start = proposal_start();
  const ProposalGate gates = all_gates(), labelled_gates = this->labelled_gates();
  const Calibration fit = calibrate_gated(all_segments(), start, gates);
  const ProposalThresholds made = proposal_thresholds(fit, labelled.segments, start, proposal_params(), {},
                                                      {labelled_gates.may_mark, labelled_gates.may_bound});
  follow_proposals(made);
  const std::size_t proposed = refresh_proposals(made.thresholds);
  proposal_summary_ = std::to_string(proposed) + " proposals (marking " + std::string(to_string(made.marking)) +
                      ", boundary " + std::string(to_string(made.boundary)) + ")";
  // With guidance (its own line in the status bar and the Train tab) the note would repeat it.
  if (guidance_.empty() && !made.note.empty()) proposal_summary_ += "; " + made.note;
  autosave();
  return proposal_summary_;
}

Label StudioController::proposal(std::size_t segment) const {
  if (image_count() == 0) return Label::Unlabelled;
  const ImageEntry& e = project_.images[current_];
  if (segment >= e.segments.size() || e.segments[segment].label != Label::Unlabelled) return Label::Unlabelled;
  return e.proposal(segment);
}

std::size_t StudioController::accept_proposals() {
  if (image_count() == 0) return 0;
  std::vector<LabelEdit> edits;
  const ImageEntry& e = project_.images[current_];
  for (std::size_t i = 0; i < e.segments.size(); ++i)
    if (const Label p = proposal(i); p != Label::Unlabelled) edits.push_back({{current_, i}, Label::Unlabelled, p});
  const std::size_t accepted = edits.size();
  if (accepted && history_.apply(project_, edits, "accept " + std::to_string(accepted) + " proposals"))
    after_label_change();
  // On to the next image (wrapping) that still holds something to review.
  for (std::size_t step = 1; step <= image_count(); ++step) {
    const std::size_t i = (current_ + step) % image_count();
    if (progress(i).labelled < project_.images[i].segments.size()) {
      select_image(i);
      break;
    }
  }
  return accepted;
}

std::size_t StudioController::to_review() const {
  std::size_t segments = 0;
  for (const ImageEntry& e : project_.images) segments += e.segments.size();
  return segments - labelled_total();
}

std::optional<StudioController::Uncertain> StudioController::least_certain(std::size_t image) const {
  // Proposals were made with their own thresholds: rank by those once there are any.
  const Thresholds& t = proposal_thresholds_ ? *proposal_thresholds_ : project_.thresholds;
  // A segment the robot's gates decide (proposal_gate.hpp) comes after every other: its colour
  // margin is no doubt about its proposal. Still reachable once nothing else is left.
  constexpr double kDecided = 1e12;
  const ProposalGate& gate = detection_.gate(image);
  std::optional<Uncertain> best;
  const auto& segs = project_.images[image].segments;
  const bool gated = gate.covers(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (segs[i].label != Label::Unlabelled) continue;
    const double m = std::abs(decision_margin(features_[image][i], t)) + (gated && gate.decided(i) ? kDecided : 0);
    if (!best || m < best->margin) best = Uncertain{i, m};
  }
  return best;
}

double StudioController::image_uncertainty(std::size_t image) const {
  const auto u = image < image_count() ? least_certain(image) : std::nullopt;
  return u ? u->margin : std::numeric_limits<double>::infinity();
}

std::vector<std::size_t> StudioController::images_by_uncertainty() const {
  std::vector<std::pair<double, std::size_t>> keyed;
  for (std::size_t i = 0; i < image_count(); ++i) keyed.emplace_back(image_uncertainty(i), i);
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::size_t> order;
  for (const auto& [margin, image] : keyed) order.push_back(image);
  return order;
}

std::optional<SegmentRef> StudioController::focus_most_uncertain() {
  std::optional<SegmentRef> best;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t img = 0; img < image_count(); ++img)
    if (const auto u = least_certain(img); u && u->margin < least) least = u->margin, best = SegmentRef{img, u->segment};
  if (!best) return best;
  select_image(best->image);
  set_hovered(best->segment);
  focus_request_ = best->segment;
  return best;
}

std::optional<std::size_t> StudioController::take_focus_request() {
  return std::exchange(focus_request_, std::nullopt);
}

}  // namespace fieldlines::studio
