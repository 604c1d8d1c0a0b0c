#include "gui/model/class_switch.hpp"

#include "fieldlines/train/calibrate.hpp"

namespace fieldlines::studio {

ClassThresholds& class_thresholds(Thresholds& t, Label cls) {
  return cls == Label::Boundary ? t.boundary.thresholds : t.marking.thresholds;
}

const ClassThresholds& class_thresholds(const Thresholds& t, Label cls) {
  return cls == Label::Boundary ? t.boundary.thresholds : t.marking.thresholds;
}

bool class_on(const Thresholds& t, Label cls) { return class_thresholds(t, cls) != disabled_class(); }

}  // namespace fieldlines::studio
