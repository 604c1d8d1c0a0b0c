#include "gui/model/ui_state.hpp"

namespace fieldlines::studio {

const char* panel_name(Panel panel) {
  switch (panel) {
    case Panel::Images: return "Images";
    case Panel::Label: return "Label";
    case Panel::Thresholds: return "Thresholds";
    case Panel::Train: return "Train";
    case Panel::Metrics: return "Metrics";
    case Panel::Export: return "Export";
    case Panel::Camera: return "Camera";
    case Panel::Count: break;
  }
  return "?";
}

}  // namespace fieldlines::studio
