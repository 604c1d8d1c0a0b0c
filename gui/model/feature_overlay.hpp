#pragma once
// What the image view draws for a frame's field features (fieldlines/detect/field_features.hpp),
// as screen-space primitives: window-free, so a test checks the drawing without ImGui. Colours
// and outlines are the CLI's `detect --draw` ones (palette.hpp: kFieldBoundary, kFeature, each
// over the kOutline rule of every segment), so a picture means the same in both:
//  - field boundary: the hull polyline, dashed white (the segments' dash pattern, running on
//    across its corners), so it never hides a segment under it;
//  - intersections: a ring at the junction, a short tick along each ray, the type letter L/T/X
//    up and right of the ring;
//  - centre circle: the fitted ellipse as a closed polyline;
//  - stripes: each centre line with a bar across each end as long as the paint is wide (a
//    translucent band of that width costs a sixth more frame time under a software renderer:
//    docs/studio.md).
// Widths follow the segments' (ViewSettings::segment_width: the zoom and the user's factor);
// the ring and ticks are screen sizes, so a junction reads at every zoom.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fieldlines/detect/field_features.hpp"
#include "gui/model/feature_layers.hpp"
#include "gui/model/geometry.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/view_settings.hpp"
#include "gui/model/view_transform.hpp"

namespace fieldlines::studio {

// A line drawn as a segment is (its outline, then its stroke).
struct FeatureLine {
  Vec2 a, b;
  SegmentStyle style;
};
// A ring of `radius` screen px, drawn over a ring of kOutline kOutlineExtra px wider.
struct FeatureRing {
  Vec2 centre;
  float radius = 0;
  SegmentStyle style;
};
// One letter whose bottom-left corner is `at`, drawn over a kOutline shadow.
struct FeatureLetter {
  Vec2 at;
  char letter = 0;
  Rgba colour;
};

struct FeatureDrawing {
  std::vector<FeatureLine> lines;  // drawn first
  std::vector<FeatureRing> rings;
  std::vector<FeatureLetter> letters;  // drawn last
  void clear() {
    lines.clear(), rings.clear(), letters.clear();
  }
  bool empty() const { return lines.empty() && rings.empty() && letters.empty(); }
};

// Segments of the closed polyline approximating an ellipse.
inline constexpr int kEllipseSteps = 64;
// The features' line width, screen px: a segment's as drawn (ViewSettings::drawn_width: whole
// pixels, at least 1).
float feature_thickness(const ViewSettings& settings, float view_scale);

// The primitives for the layers that are on, into `out` (cleared; its capacity is reused, as the
// view builds it every frame). Features with a non-finite coordinate or an empty size are skipped.
void build_feature_drawing(const FieldFeatures& features, const FeatureLayers& layers, const ViewTransform& view,
                           const ViewSettings& settings, FeatureDrawing& out);

}  // namespace fieldlines::studio
