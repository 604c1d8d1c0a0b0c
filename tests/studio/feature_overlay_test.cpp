// The field features on the canvas without a window: the four layers and what each draws for a
// FieldFeatures at a view (gui/model/feature_overlay.hpp): where, in which palette colour, how
// wide, and nothing for a layer that is off or a feature that is not finite.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fieldlines/data/palette.hpp"
#include "gui/model/feature_overlay.hpp"

namespace fs = fieldlines::studio;
using fieldlines::FieldFeatures;
using fieldlines::Intersection;
using fieldlines::JunctionType;
using fieldlines::Marking;
using fieldlines::MarkingEllipse;
using fs::FeatureLayer;

namespace {

constexpr fs::Rgba rgba(fieldlines::palette::Rgb c) { return {c.r, c.g, c.b, 255}; }

fs::FeatureLayers only(FeatureLayer layer) {
  fs::FeatureLayers layers;
  layers.set(layer, true);
  return layers;
}

// A view at `scale` screen px per image px, image origin at screen (10, 20).
fs::ViewTransform view_at(float scale) {
  fs::ViewTransform view;
  view.set(scale, {10, 20});
  return view;
}

fs::FeatureDrawing draw(const FieldFeatures& f, const fs::FeatureLayers& layers, float scale = 1,
                        fs::ViewSettings settings = {}) {
  fs::FeatureDrawing out;
  fs::build_feature_drawing(f, layers, view_at(scale), settings, out);
  return out;
}

float length(fs::Vec2 a, fs::Vec2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

FieldFeatures one_of_each() {
  FieldFeatures f;
  f.markings.push_back({10, 50, 110, 50, 6});  // horizontal, 100 px long, 6 px wide
  Intersection t;
  t.x = 40, t.y = 60, t.type = JunctionType::T, t.num_rays = 3;
  t.heading_rays = {0, 1.5707964f, 3.1415927f, 0};
  f.intersections.push_back(t);
  f.ellipses.push_back({100, 80, 60, 20, 0, 1});
  f.field_boundary.points = {{0, 10}, {50, 5}, {100, 10}};
  return f;
}

}  // namespace

TEST(FeatureLayers, AllOffByDefaultEachTogglesAlone) {
  fs::FeatureLayers layers;
  EXPECT_FALSE(layers.any());
  for (const FeatureLayer l : fs::kFeatureLayers) EXPECT_FALSE(layers.on(l));
  layers.toggle(FeatureLayer::CentreCircle);
  EXPECT_TRUE(layers.on(FeatureLayer::CentreCircle));
  EXPECT_FALSE(layers.on(FeatureLayer::Stripes));
  EXPECT_TRUE(layers.any());
  layers.toggle(FeatureLayer::CentreCircle);
  EXPECT_EQ(layers, fs::FeatureLayers{});
  const fs::FeatureLayers all = fs::FeatureLayers::all();
  for (const FeatureLayer l : fs::kFeatureLayers) {
    EXPECT_TRUE(all.on(l));
    EXPECT_FALSE(fs::feature_layer_name(l).empty());
  }
  EXPECT_TRUE(fs::ViewSettings{}.features == fs::FeatureLayers{});  // the canvas starts without them
}

TEST(FeatureOverlay, NothingWhenEveryLayerIsOffOrThereAreNoFeatures) {
  EXPECT_TRUE(draw(one_of_each(), {}).empty());
  EXPECT_TRUE(draw(FieldFeatures{}, fs::FeatureLayers::all()).empty());
  fs::FeatureDrawing reused = draw(one_of_each(), fs::FeatureLayers::all());
  ASSERT_FALSE(reused.empty());
  fs::build_feature_drawing(FieldFeatures{}, fs::FeatureLayers::all(), view_at(1), {}, reused);
  EXPECT_TRUE(reused.empty());  // cleared, not appended to
}

TEST(FeatureOverlay, AStripeIsItsCentreLineWithABarAsWideAsThePaintAtEachEnd) {
  const fs::FeatureDrawing d = draw(one_of_each(), only(FeatureLayer::Stripes), 2);
  ASSERT_EQ(d.lines.size(), 3u);
  EXPECT_TRUE(d.rings.empty() && d.letters.empty());
  // Image (10, 50) - (110, 50) at the pixel centres, scale 2, offset (10, 20).
  EXPECT_EQ(d.lines[0].a, (fs::Vec2{10 + 10.5f * 2, 20 + 50.5f * 2}));
  EXPECT_EQ(d.lines[0].b, (fs::Vec2{10 + 110.5f * 2, 20 + 50.5f * 2}));
  for (const fs::FeatureLine& l : d.lines) {
    EXPECT_EQ(l.style.colour, rgba(fieldlines::palette::kFeature));
    EXPECT_EQ(l.style.stroke, fs::Stroke::Solid);
  }
  // The bars: across the line (vertical here), 6 px wide paint at scale 2 = 12 screen px.
  for (const fs::FeatureLine& bar : {d.lines[1], d.lines[2]}) {
    EXPECT_FLOAT_EQ(bar.a.x, bar.b.x);
    EXPECT_NEAR(length(bar.a, bar.b), 12, 1e-4);
  }
  EXPECT_FLOAT_EQ(d.lines[1].a.x, d.lines[0].a.x);
  EXPECT_FLOAT_EQ(d.lines[2].a.x, d.lines[0].b.x);
  // Paint thinner than the line on screen still gets a bar twice the line's width.
  FieldFeatures thin;
  thin.markings.push_back({0, 0, 50, 0, 0.1f});
  const fs::FeatureDrawing t = draw(thin, only(FeatureLayer::Stripes));
  ASSERT_EQ(t.lines.size(), 3u);
  EXPECT_NEAR(length(t.lines[1].a, t.lines[1].b), 2 * t.lines[0].style.thickness, 1e-4);
  // No width measured: the centre line alone.
  thin.markings[0].width = 0;
  EXPECT_EQ(draw(thin, only(FeatureLayer::Stripes)).lines.size(), 1u);
}

TEST(FeatureOverlay, AJunctionIsARingItsRayTicksAndItsTypeLetter) {
  const fs::FeatureDrawing d = draw(one_of_each(), only(FeatureLayer::Intersections));
  ASSERT_EQ(d.rings.size(), 1u);
  ASSERT_EQ(d.lines.size(), 3u);  // a T: three rays
  ASSERT_EQ(d.letters.size(), 1u);
  const fs::Vec2 centre{10 + 40.5f, 20 + 60.5f};
  EXPECT_EQ(d.rings[0].centre, centre);
  const float thickness = fs::feature_thickness({}, 1);
  EXPECT_FLOAT_EQ(d.rings[0].radius, fieldlines::palette::junction_ring_radius(thickness));
  EXPECT_EQ(d.rings[0].style.colour, rgba(fieldlines::palette::kFeature));
  // Each tick runs from the ring out along its heading: +x, +y (image down), -x.
  const fs::Vec2 directions[] = {{1, 0}, {0, 1}, {-1, 0}};
  for (std::size_t k = 0; k < 3; ++k) {
    const fs::FeatureLine& tick = d.lines[k];
    EXPECT_NEAR(length(centre, tick.a), fieldlines::palette::junction_ring_radius(thickness), 1e-3);
    EXPECT_NEAR(length(centre, tick.b), fieldlines::palette::junction_tick_length(thickness), 1e-3);
    EXPECT_NEAR((tick.b.x - tick.a.x) / length(tick.a, tick.b), directions[k].x, 1e-5);
    EXPECT_NEAR((tick.b.y - tick.a.y) / length(tick.a, tick.b), directions[k].y, 1e-5);
  }
  EXPECT_EQ(d.letters[0].letter, 'T');
  EXPECT_GT(d.letters[0].at.x, centre.x + d.rings[0].radius);  // up and right of the ring
  EXPECT_LT(d.letters[0].at.y, centre.y - d.rings[0].radius);
  // Every type gets its letter and its number of rays (at most 4 whatever num_rays says).
  FieldFeatures f;
  for (const auto& [type, rays] : {std::pair{JunctionType::L, 2}, std::pair{JunctionType::X, 4}}) {
    Intersection j;
    j.type = type, j.num_rays = rays;
    f.intersections.push_back(j);
  }
  f.intersections.push_back(f.intersections.back());
  f.intersections.back().num_rays = 9;
  const fs::FeatureDrawing all = draw(f, only(FeatureLayer::Intersections));
  EXPECT_EQ(all.lines.size(), 2u + 4u + 4u);
  ASSERT_EQ(all.letters.size(), 3u);
  EXPECT_EQ(all.letters[0].letter, 'L');
  EXPECT_EQ(all.letters[1].letter, 'X');
}

TEST(FeatureOverlay, TheCentreCircleIsAClosedPolylineOnTheEllipse) {
  FieldFeatures f;
  f.ellipses.push_back({100, 80, 60, 20, 90, 1});  // 60 wide along 90 degrees: 60 tall on screen
  const fs::FeatureDrawing d = draw(f, only(FeatureLayer::CentreCircle), 1);
  ASSERT_EQ(d.lines.size(), static_cast<std::size_t>(fs::kEllipseSteps));
  EXPECT_NEAR(length(d.lines.front().a, d.lines.back().b), 0, 1e-3);  // closed
  const fs::Vec2 centre{10 + 100.5f, 20 + 80.5f};
  for (const fs::FeatureLine& l : d.lines) {
    // On the ellipse: ((x - cx) / 10)^2 + ((y - cy) / 30)^2 = 1, as the angle turns it upright.
    const float u = (l.a.x - centre.x) / 10, v = (l.a.y - centre.y) / 30;
    EXPECT_NEAR(u * u + v * v, 1, 1e-3);
    EXPECT_EQ(l.style.colour, rgba(fieldlines::palette::kFeature));
  }
}

TEST(FeatureOverlay, TheFieldBoundaryIsDashedWhiteWithThePatternRunningOnAcrossCorners) {
  FieldFeatures f;
  // 200 px of boundary in 40 pieces of 5 px: shorter than a dash, so only a pattern that runs
  // on across the corners leaves gaps.
  for (int i = 0; i <= 40; ++i) f.field_boundary.points.push_back({static_cast<float>(5 * i), 10});
  const fs::FeatureDrawing d = draw(f, only(FeatureLayer::FieldBoundary));
  ASSERT_FALSE(d.lines.empty());
  float drawn = 0;
  for (const fs::FeatureLine& l : d.lines) {
    EXPECT_EQ(l.style.colour, rgba(fieldlines::palette::kFieldBoundary));
    drawn += length(l.a, l.b);
  }
  const fs::DashPattern dash = fs::dash_pattern(fs::Stroke::Dashed, d.lines[0].style.thickness);
  EXPECT_NEAR(drawn, 200 * dash.on / dash.period, dash.on);  // the dashes' share of the length
  EXPECT_LT(drawn, 0.9f * 200);
}

TEST(FeatureOverlay, WidthsFollowTheZoomAndTheUsersFactorLikeSegmentsInWholePixels) {
  fs::ViewSettings wide;
  wide.set_line_width(2);
  const fs::FeatureDrawing base = draw(one_of_each(), only(FeatureLayer::CentreCircle), 1);
  const fs::FeatureDrawing widened = draw(one_of_each(), only(FeatureLayer::CentreCircle), 1, wide);
  const fs::FeatureDrawing zoomed = draw(one_of_each(), only(FeatureLayer::CentreCircle), 16);
  EXPECT_FLOAT_EQ(base.lines[0].style.thickness, fs::ViewSettings{}.segment_width(2, 1));  // 2: whole already
  EXPECT_FLOAT_EQ(widened.lines[0].style.thickness, 2 * base.lines[0].style.thickness);
  EXPECT_FLOAT_EQ(zoomed.lines[0].style.thickness, 4 * base.lines[0].style.thickness);
  // Between: the segment's width rounded (zoom 1.8: 2 * sqrt(1.8) = 2.68 -> 3), never below 1.
  EXPECT_FLOAT_EQ(fs::feature_thickness({}, 1.8f), 3);
  fs::ViewSettings thin;
  thin.set_line_width(0.5f);
  EXPECT_FLOAT_EQ(fs::feature_thickness(thin, 1), 1);
  for (const float scale : {0.3f, 1.34f, 2.5f, 7.0f}) {
    const float t = fs::feature_thickness({}, scale);
    EXPECT_EQ(t, std::round(t)) << scale;
    EXPECT_NEAR(t, fs::ViewSettings{}.segment_width(2, scale), 0.5f) << scale;
  }
}

TEST(FeatureOverlay, FeaturesThatAreNotFiniteAreSkipped) {
  constexpr float nan = std::numeric_limits<float>::quiet_NaN();
  constexpr float inf = std::numeric_limits<float>::infinity();
  FieldFeatures f;
  f.markings.push_back({nan, 0, 10, 10, 3});
  f.markings.push_back({0, 0, 10, 10, inf});  // a line without its width
  Intersection j;
  j.x = inf;
  f.intersections.push_back(j);
  f.ellipses.push_back({0, 0, nan, 10, 0, 1});
  f.ellipses.push_back({0, 0, -5, 10, 0, 1});
  f.field_boundary.points = {{0, 0}, {nan, 1}};
  const fs::FeatureDrawing d = draw(f, fs::FeatureLayers::all());
  EXPECT_EQ(d.lines.size(), 1u);
  EXPECT_TRUE(d.rings.empty() && d.letters.empty());
}
