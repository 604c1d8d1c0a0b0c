// Per-class on/off and calibration's verdicts, part of StudioController (class_switch.hpp says
// why a class is switched off by its thresholds). In its own file: one concept, which classes
// the field has, decided by the user or, until the user decides, by calibration.
#include "fieldlines/train/calibrate.hpp"
#include "gui/model/refusal_guidance.hpp"
#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

ClassSwitch& StudioController::class_switch(Label cls) { return switches_[cls == Label::Boundary ? 1 : 0]; }

const ClassSwitch& StudioController::class_switch(Label cls) const { return switches_[cls == Label::Boundary ? 1 : 0]; }

bool StudioController::class_on(Label cls) const { return studio::class_on(project_.thresholds, cls); }

const std::string& StudioController::class_off_reason(Label cls) const {
  static const std::string on;  // a class turned on by other means (Reset, Import) keeps no reason
  return class_on(cls) ? on : class_switch(cls).off_because;
}

void StudioController::switch_class(Label cls, bool on, const ClassThresholds& when_on) {
  if (on == class_on(cls)) return;
  Thresholds t = project_.thresholds;
  if (!on) class_switch(cls).restore = class_thresholds(t, cls);
  class_thresholds(t, cls) = on ? when_on : disabled_class();
  set_thresholds(t);
  // Proposals follow at once: a class switched off is never proposed.
  if (proposal_thresholds_) {
    class_thresholds(*proposal_thresholds_, cls) = class_thresholds(t, cls);
    refresh_proposals(*proposal_thresholds_);
  }
}

void StudioController::set_class_on(Label cls, bool on) {
  class_switch(cls).off_because.clear();  // the user decides, not calibration
  if (on == class_on(cls)) return;
  switch_class(cls, on, class_switch(cls).restore);
  // The other class is trained with this one's test first (classifier.hpp): retrain it. A
  // verdict of calibration needs none: the run that brought it trained with it.
  live_.labels_changed();
}

Thresholds StudioController::proposal_start() const {
  Thresholds t = project_.thresholds;
  for (const Label cls : kSwitchableClasses)
    if (!class_on(cls) && !class_off_reason(cls).empty()) class_thresholds(t, cls) = class_switch(cls).restore;
  return t;
}

void StudioController::follow_proposals(const ProposalThresholds& made) {
  for (const Label cls : kSwitchableClasses) {
    const bool boundary = cls == Label::Boundary;
    const ProposalSource source = boundary ? made.boundary : made.marking;
    const std::string& refused = boundary ? made.boundary_refused : made.marking_refused;
    ClassSwitch& s = class_switch(cls);
    if (source == ProposalSource::Disabled && !refused.empty()) {
      // A class the user switched off never gets here: proposals leave it off without asking.
      switch_class(cls, false, {});
      s.off_because = refused;
    } else if (!s.off_because.empty() && source != ProposalSource::Disabled) {
      s.off_because.clear();  // labels or calibration found the class after all
      switch_class(cls, true, class_thresholds(made.thresholds, cls));
    }
  }
  guidance_ = refusal_guidance(made, proposal_params());
}

}  // namespace fieldlines::studio
