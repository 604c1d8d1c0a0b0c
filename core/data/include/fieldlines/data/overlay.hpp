#pragma once
// Drawing detected segments over their image, coloured by label, for a human to check.
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/data/palette.hpp"
#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

// A palette colour as OpenCV's BGR.
inline cv::Scalar bgr(palette::Rgb c) {
  return {static_cast<double>(c.b), static_cast<double>(c.g), static_cast<double>(c.r)};
}

struct OverlayParams {
  // BGR; the studio's palette (fieldlines/data/palette.hpp: legible on turf, white lines and a
  // dark wall) unless overridden.
  cv::Scalar marking_colour = bgr(palette::kMarking);
  cv::Scalar boundary_colour = bgr(palette::kBoundary);
  cv::Scalar none_colour = bgr(palette::kNone);
  cv::Scalar unlabelled_colour = bgr(palette::kUnlabelled);
  cv::Scalar outline_colour = bgr(palette::kOutline);
  int thickness = 0;      // line width in pixels; 0 picks one from the image size (>= 1)
  // A dark border this many pixels wide on each side of every segment and endpoint dot, as the
  // studio draws (palette.hpp); 0 draws none. Per side rather than palette::kOutlineExtra in
  // total because OpenCV rounds anti-aliased widths to odd ones: 2 leaves >= 1 solid pixel.
  int outline_px = 2;
  bool endpoints = true;  // small dots at the endpoints show where segments split
  // Label names and counts in the top-left corner, and the field features' in the top-right
  // (draw_field_features); each skipped when it won't fit.
  bool legend = true;
  // What lies on the field reads first: segments above this boundary (stands, walls, lights)
  // are drawn at `above_opacity` (0 hides them, 1 draws them like the rest); null or an empty
  // boundary: every segment alike.
  const FieldBoundary* field_boundary = nullptr;
  double above_opacity = palette::kAboveFieldOpacity;
};

cv::Scalar label_colour(Label label, const OverlayParams& params = {});

// The frame's field boundary (fieldlines/detect/field_boundary.hpp) as a polyline, dashed so
// that it never hides a segment under it, over the same dark outline.
void draw_field_boundary(cv::Mat& canvas, std::span<const FieldBoundary::Point> boundary,
                         const OverlayParams& params = {});

// The field features (fieldlines/detect/field_features.hpp) over the same dark outline: the
// markings' centre lines, the ellipses, each intersection as a ring with its rays and its type
// letter, and the field boundary (draw_field_boundary); with `legend`, what each colour is.
void draw_field_features(cv::Mat& canvas, const FieldFeatures& features, const OverlayParams& params = {});

// Returns an 8-bit BGR copy of `image` (any type load_image accepts) with the segments drawn.
cv::Mat draw_overlay(const cv::Mat& image, std::span<const Segment> segments,
                     const OverlayParams& params = {});

}  // namespace fieldlines
