#pragma once
// The Train tab's settings and what its Apply reports, window-free: the PSO parameters (as
// `fieldlines train` trains by default), the particle scatter's two dimensions, starting and
// stopping a run, and the "applied: ..." line shown while the applied thresholds still hold.
#include <optional>
#include <string>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/train/protocols.hpp"
#include "fieldlines/train/training.hpp"

namespace fieldlines::studio {

class StudioController;

class TrainForm {
 public:
  TrainParams params = protocol_spec(Protocol::Ours).train;
  int scatter_x = 0, scatter_y = 1;  // threshold dimensions of the particle scatter

  // Starts PSO training with `params`, or stops the run (Ctrl+T, Start / Stop).
  void toggle(StudioController& controller) const;
  // Adopts the finished training's thresholds and records what they score on the test split
  // (on train when the test split is empty); false when there is no successful result.
  bool apply(StudioController& controller);
  // What the last Apply did, while its thresholds are still the current ones (a slider, an
  // import, auto-train or another run end that); empty otherwise.
  const std::string& applied_message(const StudioController& controller) const;

 private:
  std::string applied_message_;
  std::optional<Thresholds> applied_thresholds_;
};

}  // namespace fieldlines::studio
