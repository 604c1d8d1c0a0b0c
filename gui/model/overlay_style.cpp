#include "gui/model/overlay_style.hpp"

#include "fieldlines/detect/enum_names.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fieldlines::studio {

namespace {
constexpr Rgba kMarking{255, 40, 200, 255};    // magenta
constexpr Rgba kBoundary{30, 120, 255, 255};   // blue
constexpr Rgba kNone{255, 210, 0, 255};        // yellow
constexpr Rgba kUnlabelled{255, 70, 20, 255};  // vermilion: still to do, must stand out on turf
constexpr Rgba kNegative{150, 150, 150, 160};  // translucent grey: agreed "not a feature"

constexpr std::array kLabelLegend{
    LegendEntry{"marking", {kMarking, Stroke::Solid, 2}},
    LegendEntry{"boundary", {kBoundary, Stroke::Solid, 2}},
    LegendEntry{"none", {kNone, Stroke::Solid, 2}},
    LegendEntry{"unlabelled", {kUnlabelled, Stroke::Solid, 2}},
    LegendEntry{"proposed (P), Enter accepts", {kMarking, Stroke::Dashed, 2}},
};
constexpr std::array kPredictionLegend{
    LegendEntry{"predicted marking", {kMarking, Stroke::Solid, 2}},
    LegendEntry{"predicted boundary", {kBoundary, Stroke::Solid, 2}},
    LegendEntry{"predicted none", {kNone, Stroke::Solid, 1}},
};
constexpr std::array kAgreementLegend{
    LegendEntry{"true positive (class colour)", {kMarking, Stroke::Solid, 2}},
    LegendEntry{"false positive (predicted class)", {kMarking, Stroke::Dashed, 2}},
    LegendEntry{"false negative (labelled class)", {kMarking, Stroke::Dotted, 2}},
    LegendEntry{"true negative", {kNegative, Stroke::Solid, 1}},
    LegendEntry{"unlabelled", {kUnlabelled, Stroke::Dotted, 2}},
};
}  // namespace

constexpr EnumNames<OverlayMode, 3> kModeNames{
    {{{OverlayMode::Labels, "labels"}, {OverlayMode::Prediction, "prediction"}, {OverlayMode::Agreement, "agreement"}}}};
std::string_view to_string(OverlayMode mode) { return kModeNames.name(mode); }

Rgba label_colour(Label label) {
  switch (label) {
    case Label::Marking: return kMarking;
    case Label::Boundary: return kBoundary;
    case Label::None: return kNone;
    case Label::Unlabelled: return kUnlabelled;
  }
  return kUnlabelled;
}

SegmentStyle style_for(OverlayMode mode, Label truth, Label predicted, Label proposal) {
  if (mode != OverlayMode::Prediction && truth == Label::Unlabelled && proposal != Label::Unlabelled)
    return {label_colour(proposal), Stroke::Dashed, 2};
  switch (mode) {
    case OverlayMode::Labels:
      return {label_colour(truth), Stroke::Solid, 2.0f};
    case OverlayMode::Prediction:
      return {label_colour(predicted), Stroke::Solid, predicted == Label::None ? 1.0f : 2.0f};
    case OverlayMode::Agreement:
      if (truth == Label::Unlabelled) return {kUnlabelled, Stroke::Dotted, 2};
      if (truth == predicted) {
        return truth == Label::None ? SegmentStyle{kNegative, Stroke::Solid, 1} : SegmentStyle{label_colour(truth), Stroke::Solid, 2};
      }
      // A wrong feature prediction is a false positive of the predicted class (drawn dashed),
      // even when it is also a false negative of the labelled one.
      if (predicted != Label::None) return {label_colour(predicted), Stroke::Dashed, 2};
      return {label_colour(truth), Stroke::Dotted, 2};
  }
  return {};
}

float zoomed_thickness(float thickness, float scale) {
  return thickness * std::clamp(std::sqrt(scale), 1.0f, 4.0f);
}

std::span<const LegendEntry> legend(OverlayMode mode) {
  switch (mode) {
    case OverlayMode::Labels: return kLabelLegend;
    case OverlayMode::Prediction: return kPredictionLegend;
    case OverlayMode::Agreement: return kAgreementLegend;
  }
  return {};
}

}  // namespace fieldlines::studio
