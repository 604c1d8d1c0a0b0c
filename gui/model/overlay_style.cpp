#include "gui/model/overlay_style.hpp"

#include "fieldlines/detect/enum_names.hpp"
#include "gui/model/shortcuts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace fieldlines::studio {

namespace {
constexpr Rgba opaque(palette::Rgb c, std::uint8_t alpha = 255) { return {c.r, c.g, c.b, alpha}; }
constexpr Rgba kMarking = opaque(palette::kMarking);
constexpr Rgba kBoundary = opaque(palette::kBoundary);
constexpr Rgba kNone = opaque(palette::kNone);
constexpr Rgba kUnlabelled = opaque(palette::kUnlabelled);
constexpr Rgba kNegative = opaque(palette::kQuiet, 160);  // translucent grey: agreed "not a feature"

constexpr LegendEntry class_entry(Label label, const char* text, float thickness = 2) {
  return {text, {opaque(palette::label_rgb(label)), Stroke::Solid, thickness}, palette::label_transition(label)};
}

// Built on first use: the proposal row names its keys from the shortcut table.
std::span<const LegendEntry> label_legend() {
  static const std::string proposed = "proposed (" + key_for(Action::Propose) + "), " +
                                      key_for(Action::AcceptProposals) + " accepts";
  static const std::array rows{
      class_entry(Label::Marking, "marking"),
      class_entry(Label::Boundary, "boundary"),
      class_entry(Label::None, "none"),
      LegendEntry{"unlabelled", {kUnlabelled, Stroke::Solid, 2}},
      LegendEntry{proposed, {kMarking, Stroke::Dashed, 2}},
  };
  return rows;
}
constexpr std::array kPredictionLegend{
    class_entry(Label::Marking, "predicted marking"),
    class_entry(Label::Boundary, "predicted boundary"),
    class_entry(Label::None, "predicted none", 1),
};
constexpr std::array kAgreementLegend{
    LegendEntry{"true positive (class colour)", {kMarking, Stroke::Solid, 2}},
    LegendEntry{"false positive (predicted class)", {kMarking, Stroke::Dashed, 2}},
    LegendEntry{"false negative (labelled class)", {kMarking, Stroke::Dotted, 2}},
    LegendEntry{"true negative", {kNegative, Stroke::Solid, 1}},
    LegendEntry{"unlabelled", {kUnlabelled, Stroke::Dotted, 2}},
    class_entry(Label::Marking, "marking"),
    class_entry(Label::Boundary, "boundary"),
    class_entry(Label::None, "none"),
};
}  // namespace

constexpr EnumNames<OverlayMode, 3> kModeNames{
    {{{OverlayMode::Labels, "labels"}, {OverlayMode::Prediction, "prediction"}, {OverlayMode::Agreement, "agreement"}}}};
std::string_view to_string(OverlayMode mode) { return kModeNames.name(mode); }

Rgba label_colour(Label label) { return opaque(palette::label_rgb(label)); }

SegmentStyle on_field_style(SegmentStyle style, const Segment& segment, const FieldBoundary& boundary, bool faint) {
  if (faint && !boundary.empty() && place_of(segment, boundary) == BoundaryPlace::Above)
    style.colour.a = static_cast<std::uint8_t>(std::lround(palette::kAboveFieldOpacity * style.colour.a));
  return style;
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

DashPattern dash_pattern(Stroke stroke, float thickness) {
  const float t = std::max(thickness, 0.0f);
  // A dot a little wider than the line, so its roundness shows; at least 3 px to be seen at all.
  const float dot = std::max(1.25f * t, 3.0f);
  const float gap = std::max(1.5f * t, 3.0f);  // wide enough to show the outline between pieces
  switch (stroke) {
    case Stroke::Solid: return {1, 1, false};
    case Stroke::Dashed: return {4 * dot, 4 * dot + gap, false};
    case Stroke::Dotted: return {dot, dot + gap, true};
  }
  return {1, 1, false};
}

void dash_pieces(Stroke stroke, float thickness, float length, std::vector<DashPiece>& out) {
  out.clear();
  if (!(length > 0)) return;
  if (stroke == Stroke::Solid) {
    out.push_back({0, length});
    return;
  }
  const DashPattern p = dash_pattern(stroke, thickness);
  if (p.round) {
    if (length < p.on) {
      out.push_back({0.5f * (length - p.on), 0.5f * (length + p.on)});  // one dot, centred
      return;
    }
    for (float t = 0; t + p.on <= length; t += p.period) out.push_back({t, t + p.on});
    return;
  }
  for (float t = 0; t < length; t += p.period) out.push_back({t, std::min(t + p.on, length)});
}

std::vector<DashPiece> dash_pieces(Stroke stroke, float thickness, float length) {
  std::vector<DashPiece> out;
  dash_pieces(stroke, thickness, length, out);
  return out;
}

std::span<const LegendEntry> legend(OverlayMode mode) {
  switch (mode) {
    case OverlayMode::Labels: return label_legend();
    case OverlayMode::Prediction: return kPredictionLegend;
    case OverlayMode::Agreement: return kAgreementLegend;
  }
  return {};
}

}  // namespace fieldlines::studio
