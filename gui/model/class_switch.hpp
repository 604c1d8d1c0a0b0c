#pragma once
// Per-class on/off. A field may lack a class (a Nao field has no dark wall, so no boundary);
// left on, its defaults mark shadow edges as one, in proposals and on the robot. Off is the
// thresholds file's own way to say it: thresholds no segment passes (disabled_class(), what
// `fieldlines calibrate` writes for a class it refuses), so the robot needs no new field and
// every consumer of Thresholds already honours it.
#include <string>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines::studio {

// The two classes a switch exists for.
inline constexpr Label kSwitchableClasses[] = {Label::Marking, Label::Boundary};

// `cls` is Label::Marking or Label::Boundary.
ClassThresholds& class_thresholds(Thresholds& t, Label cls);
const ClassThresholds& class_thresholds(const Thresholds& t, Label cls);
bool class_on(const Thresholds& t, Label cls);

// What the controller remembers of one class besides its thresholds.
struct ClassSwitch {
  // Given back when the class is turned on again; the default thresholds until it was on here.
  ClassThresholds restore;
  // Calibration's reason when calibration turned the class off; empty when the user did (or it
  // is on). A class calibration turned off is tried again at every proposal, a user's never.
  std::string off_because;
};

}  // namespace fieldlines::studio
