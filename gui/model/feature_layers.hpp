#pragma once
// Which of the detector's field features (fieldlines/detect/field_features.hpp) the image view
// draws over the segments: four layers, each on or off (view state, not saved). All off by
// default: the canvas is for labelling segments, and a stripe's centre line or a junction's
// ring lies right on the edges being labelled; a user turns on the layer they want to check.
#include <array>
#include <cstddef>
#include <string_view>

namespace fieldlines::studio {

enum class FeatureLayer { FieldBoundary, Intersections, CentreCircle, Stripes, Count };

inline constexpr std::array<FeatureLayer, 4> kFeatureLayers{FeatureLayer::FieldBoundary, FeatureLayer::Intersections,
                                                            FeatureLayer::CentreCircle, FeatureLayer::Stripes};

// The checkbox caption: "field boundary", "intersections", "centre circle", "stripe centre lines".
std::string_view feature_layer_name(FeatureLayer layer);

class FeatureLayers {
 public:
  static FeatureLayers all() {
    FeatureLayers layers;
    layers.on_.fill(true);
    return layers;
  }
  bool on(FeatureLayer layer) const { return on_[index(layer)]; }
  void set(FeatureLayer layer, bool on) { on_[index(layer)] = on; }
  void toggle(FeatureLayer layer) { set(layer, !on(layer)); }
  bool any() const {
    for (const bool b : on_)
      if (b) return true;
    return false;
  }
  bool operator==(const FeatureLayers&) const = default;

 private:
  static std::size_t index(FeatureLayer layer) { return static_cast<std::size_t>(layer); }
  std::array<bool, static_cast<std::size_t>(FeatureLayer::Count)> on_{};
};

}  // namespace fieldlines::studio
