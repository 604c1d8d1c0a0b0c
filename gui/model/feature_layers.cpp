#include "gui/model/feature_layers.hpp"

namespace fieldlines::studio {

std::string_view feature_layer_name(FeatureLayer layer) {
  switch (layer) {
    case FeatureLayer::FieldBoundary: return "field boundary";
    case FeatureLayer::Intersections: return "intersections";
    case FeatureLayer::CentreCircle: return "centre circle";
    case FeatureLayer::Stripes: return "stripe centre lines";
    case FeatureLayer::Count: break;
  }
  return {};
}

}  // namespace fieldlines::studio
