// Overlay colours against the pictures they are drawn on: turf of every league's lighting, white
// paint and dark walls. Measured as CIE76 Delta-E (fixtures.hpp), the bound each colour must
// clear (fieldlines/data/palette.hpp states them and the measured minimums). Stroke patterns
// and the line-width setting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fieldlines/data/palette.hpp"
#include "gui/model/view_settings.hpp"

#include "fixtures.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/shortcuts.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {

std::array<int, 3> rgb(fs::Rgba c) { return {c.r, c.g, c.b}; }

// SSL carpet, a sunny Nao field, a dark artificial-turf field, a bleached sunny one, white paint.
constexpr std::array<std::array<int, 3>, 5> kBackgrounds{{{50, 140, 40}, {90, 180, 60}, {30, 90, 40}, {130, 200, 90}, {255, 255, 255}}};
// A dark grey wall and a brown-grey one behind the field.
constexpr std::array<std::array<int, 3>, 2> kDarkWalls{{{30, 30, 30}, {60, 55, 50}}};

std::string name(const std::array<int, 3>& c) {
  char text[32];
  std::snprintf(text, sizeof text, "(%d, %d, %d)", c[0], c[1], c[2]);
  return text;
}

TEST(OverlayStyle, EveryStillToDoOrFeatureColourStandsOutOnTurfAndPaint) {
  for (const Label label : {Label::Unlabelled, Label::Marking, Label::Boundary}) {
    for (const auto& background : kBackgrounds)
      EXPECT_GE(studio_test::delta_e76(rgb(fs::label_colour(label)), background), 90.0)
          << to_string(label) << " on (" << background[0] << ", " << background[1] << ", " << background[2] << ")";
  }
  // An agreed non-feature may be quieter, but never lost.
  for (const auto& background : kBackgrounds)
    EXPECT_GE(studio_test::delta_e76(rgb(fs::label_colour(Label::None)), background), 55.0);
  // The cyan of earlier versions did not clear the bar on white paint or any turf.
  EXPECT_LT(studio_test::delta_e76({0, 230, 230}, {255, 255, 255}), 90.0);
  EXPECT_LT(studio_test::delta_e76({0, 230, 230}, {50, 140, 40}), 90.0);
  // The outline is dark whatever the colour above it.
  EXPECT_LT(studio_test::lightness(rgb(fs::kOutline)), 10.0);
}

TEST(OverlayStyle, LegibleOnDarkWallsToo) {
  // A dark outline vanishes on a dark wall (Delta-E 8.5 from (30, 30, 30)), so there the colour
  // carries the segment: every class colour >= 85 from both walls, "none" >= 55 as on turf.
  double feature_min = 1e9, none_min = 1e9;
  for (const Label label : {Label::Unlabelled, Label::Marking, Label::Boundary, Label::None}) {
    for (const auto& wall : kDarkWalls) {
      const double d = studio_test::delta_e76(rgb(fs::label_colour(label)), wall);
      EXPECT_GE(d, label == Label::None ? 55.0 : 85.0) << to_string(label) << " on " << name(wall);
      double& low = label == Label::None ? none_min : feature_min;
      low = std::min(low, d);
    }
  }
  std::printf("on dark walls: class colours >= %.1f, none >= %.1f\n", feature_min, none_min);
  EXPECT_LT(studio_test::delta_e76(rgb(fs::kOutline), kDarkWalls[0]), 20.0);  // why the colour must carry it
}

TEST(OverlayStyle, TheOutlineCarriesEachColourWhereTheColourAloneIsWeak) {
  // A segment is its colour inside its outline. It reads (a) because the colour differs from its
  // own outline (>= 90), and (b) because one of the two differs from the background: the larger
  // of the two >= 75 on every turf, white paint and dark wall, for every class including "none",
  // whose yellow alone is only 58 from the sunny turf.
  double inside_min = 1e9, stroke_min = 1e9, none_alone_min = 1e9;
  for (const Label label : {Label::Unlabelled, Label::Marking, Label::Boundary, Label::None}) {
    const auto c = rgb(fs::label_colour(label));
    const double inside = studio_test::delta_e76(c, rgb(fs::kOutline));
    EXPECT_GE(inside, 90.0) << to_string(label);
    inside_min = std::min(inside_min, inside);
    std::vector<std::array<int, 3>> all(kBackgrounds.begin(), kBackgrounds.end());
    all.insert(all.end(), kDarkWalls.begin(), kDarkWalls.end());
    for (const auto& bg : all) {
      const double alone = studio_test::delta_e76(c, bg);
      const double stroke = std::max(alone, studio_test::delta_e76(rgb(fs::kOutline), bg));
      EXPECT_GE(stroke, 75.0) << to_string(label) << " on " << name(bg);
      stroke_min = std::min(stroke_min, stroke);
      if (label == Label::None) none_alone_min = std::min(none_alone_min, alone);
    }
  }
  std::printf("colour vs its outline >= %.1f; colour-or-outline vs background >= %.1f; none alone >= %.1f\n",
              inside_min, stroke_min, none_alone_min);
  EXPECT_GT(stroke_min, none_alone_min);  // the outline does lift "none"
}

TEST(OverlayStyle, TheStudioAndTheCliDrawOnePalette) {
  for (const Label label : {Label::Unlabelled, Label::Marking, Label::Boundary, Label::None}) {
    const fieldlines::palette::Rgb p = fieldlines::palette::label_rgb(label);
    EXPECT_EQ(fs::label_colour(label), (fs::Rgba{p.r, p.g, p.b, 255})) << to_string(label);
  }
  EXPECT_EQ(fs::kOutline, (fs::Rgba{fieldlines::palette::kOutline.r, fieldlines::palette::kOutline.g,
                                    fieldlines::palette::kOutline.b, 255}));
  EXPECT_FLOAT_EQ(fs::kOutlineExtra, fieldlines::palette::kOutlineExtra);
}

TEST(OverlayStyle, EveryLegendExplainsEachClassByItsColourTransition) {
  for (const auto mode : {fs::OverlayMode::Labels, fs::OverlayMode::Prediction, fs::OverlayMode::Agreement}) {
    for (const Label label : {Label::Marking, Label::Boundary, Label::None}) {
      const auto rows = fs::legend(mode);
      const auto row = std::find_if(rows.begin(), rows.end(), [&](const fs::LegendEntry& e) {
        return e.style.colour == fs::label_colour(label) && e.detail == fieldlines::palette::label_transition(label);
      });
      EXPECT_NE(row, rows.end()) << to_string(label) << " in " << to_string(mode);
    }
  }
  EXPECT_EQ(std::string(fieldlines::palette::label_transition(Label::Marking)), "green <-> white paint");
  EXPECT_EQ(std::string(fieldlines::palette::label_transition(Label::Boundary)), "green -> black (field edge)");
  EXPECT_EQ(std::string(fieldlines::palette::label_transition(Label::None)), "anything else");
}

TEST(OverlayStyle, TheProposalRowNamesItsKeysFromTheShortcutTable) {
  const auto rows = fs::legend(fs::OverlayMode::Labels);
  const auto row = std::find_if(rows.begin(), rows.end(), [](const fs::LegendEntry& e) { return e.style.stroke == fs::Stroke::Dashed; });
  ASSERT_NE(row, rows.end());
  const std::string text(row->text);
  // Appended, not "(" + key: GCC 12 warns falsely (-Wrestrict) on a literal + std::string&&.
  std::string propose = "(";
  propose.append(fs::key_for(fs::Action::Propose)).append(")");
  EXPECT_NE(text.find(propose), std::string::npos) << text;
  EXPECT_NE(text.find(fs::key_for(fs::Action::AcceptProposals) + " accepts"), std::string::npos) << text;
}

TEST(OverlayStyle, DashesAndDotsTellApartAtFitZoom) {
  // At fit zoom a line is 2 px (zoomed_thickness never thins it); check the widths the line-width
  // setting can give too.
  for (const float t : {1.0f, 2.0f, 3.0f, 6.0f, 12.0f}) {
    const fs::DashPattern dash = fs::dash_pattern(fs::Stroke::Dashed, t);
    const fs::DashPattern dot = fs::dash_pattern(fs::Stroke::Dotted, t);
    EXPECT_GE(dash.on, 3 * dot.on) << t;       // a dash is clearly longer than a dot
    EXPECT_GE(dot.on, t) << t;                 // a dot is never shorter than it is wide
    EXPECT_GE(dot.on, 3.0f) << t;              // nor too small to see
    EXPECT_GE(dash.period - dash.on, 1.5f * t) << t;  // the gaps show (the outline between)
    EXPECT_GE(dot.period - dot.on, 1.5f * t) << t;
    EXPECT_GE(dot.period - dot.on, 3.0f) << t;
    EXPECT_TRUE(dot.round);
    EXPECT_FALSE(dash.round);
  }
  // On a 100 px line at 2 px: a few long dashes against many short dots, all inside the line.
  const auto dashes = fs::dash_pieces(fs::Stroke::Dashed, 2, 100);
  const auto dots = fs::dash_pieces(fs::Stroke::Dotted, 2, 100);
  ASSERT_FALSE(dashes.empty());
  ASSERT_FALSE(dots.empty());
  EXPECT_GE(dots.size(), 2 * dashes.size());
  for (const auto& p : dots) {
    EXPECT_GE(p.from, 0);
    EXPECT_LE(p.to, 100);
    EXPECT_FLOAT_EQ(p.to - p.from, fs::dash_pattern(fs::Stroke::Dotted, 2).on);  // never a cut dot
  }
  for (std::size_t i = 1; i < dashes.size(); ++i) EXPECT_GT(dashes[i].from, dashes[i - 1].to);
  EXPECT_EQ(fs::dash_pieces(fs::Stroke::Solid, 2, 100).size(), 1u);
  EXPECT_TRUE(fs::dash_pieces(fs::Stroke::Dotted, 2, 0).empty());
  EXPECT_EQ(fs::dash_pieces(fs::Stroke::Dotted, 2, 1).size(), 1u);  // too short for a dot: one, centred
}

TEST(OverlayStyle, TheLineWidthSettingScalesEverySegment) {
  fs::ViewSettings settings;
  EXPECT_FLOAT_EQ(settings.line_width, 1.0f);
  for (const float scale : {0.5f, 1.0f, 4.0f, 30.0f})
    EXPECT_FLOAT_EQ(settings.segment_width(2, scale), fs::zoomed_thickness(2, scale));
  settings.set_line_width(2.5f);
  EXPECT_FLOAT_EQ(settings.segment_width(2, 4), 2.5f * fs::zoomed_thickness(2, 4));
  settings.set_line_width(10);
  EXPECT_FLOAT_EQ(settings.line_width, fs::ViewSettings::kMaxLineWidth);
  settings.set_line_width(0);
  EXPECT_FLOAT_EQ(settings.line_width, fs::ViewSettings::kMinLineWidth);
  EXPECT_FLOAT_EQ(settings.segment_width(2, 1), 1.0f);
}

TEST(OverlayStyle, LinesAreDrawnInWholePixels) {
  fs::ViewSettings settings;
  EXPECT_FLOAT_EQ(settings.drawn_width(2, 1), 2);
  EXPECT_FLOAT_EQ(settings.drawn_width(2, 1.34f), 2);  // 2.32 at a typical fit zoom
  EXPECT_FLOAT_EQ(settings.drawn_width(2, 1.8f), 3);   // 2.68
  settings.set_line_width(0.5f);
  EXPECT_FLOAT_EQ(settings.drawn_width(1, 1), 1);  // never thinner than a pixel
  for (const float scale : {0.5f, 1.0f, 1.34f, 4.0f, 30.0f})
    EXPECT_NEAR(settings.drawn_width(2, scale), settings.segment_width(2, scale), 0.5f) << scale;
}

TEST(OverlayStyle, LinesGrowWithTheZoomButNeverShrink) {
  EXPECT_FLOAT_EQ(fs::zoomed_thickness(2, 1), 2);
  EXPECT_FLOAT_EQ(fs::zoomed_thickness(2, 0.25f), 2);  // zoomed out: as at 1:1
  EXPECT_FLOAT_EQ(fs::zoomed_thickness(2, 4), 4);
  EXPECT_FLOAT_EQ(fs::zoomed_thickness(2, 64), 8);     // capped at 4x
  EXPECT_GT(fs::zoomed_thickness(2, 9), fs::zoomed_thickness(2, 4));
  // Unlabelled segments are as wide as labelled ones in every mode.
  for (const auto mode : {fs::OverlayMode::Labels, fs::OverlayMode::Agreement})
    EXPECT_GE(fs::style_for(mode, Label::Unlabelled, Label::None).thickness, 2.0f);
}

}  // namespace

namespace {

TEST(OverlayStyle, AProposalIsDashedInItsClassColourAndNeverLooksLikeALabel) {
  const fs::SegmentStyle proposed = fs::style_for(fs::OverlayMode::Labels, Label::Unlabelled, Label::None, Label::Marking);
  const fs::SegmentStyle labelled = fs::style_for(fs::OverlayMode::Labels, Label::Marking, Label::None, Label::Marking);
  EXPECT_EQ(proposed.colour, fs::label_colour(Label::Marking));
  EXPECT_EQ(proposed.stroke, fs::Stroke::Dashed);
  EXPECT_EQ(labelled.stroke, fs::Stroke::Solid);
  // Once labelled, the proposal no longer shows; the prediction mode ignores proposals.
  EXPECT_EQ(fs::style_for(fs::OverlayMode::Prediction, Label::Unlabelled, Label::Boundary, Label::Marking).colour,
            fs::label_colour(Label::Boundary));
  EXPECT_EQ(fs::style_for(fs::OverlayMode::Labels, Label::Unlabelled, Label::None).colour,
            fs::label_colour(Label::Unlabelled));
}

}  // namespace

// Above the field boundary a segment's colour is faint (palette::kAboveFieldOpacity), on the
// field unchanged; off, or without a boundary, every segment alike.
TEST(OverlayStyle, SegmentsAboveTheFieldBoundaryAreFaint) {
  fieldlines::FieldBoundary field;
  field.points = {{0, 100}, {639, 100}};
  field.image_height = 480;
  fieldlines::Segment high, low;
  high.x0 = 100, high.x1 = 300, high.y0 = high.y1 = 20;
  low.x0 = 100, low.x1 = 300, low.y0 = low.y1 = 300;
  const fs::SegmentStyle style{fs::label_colour(Label::None), fs::Stroke::Solid, 2};
  EXPECT_EQ(fs::on_field_style(style, low, field, true).colour, style.colour);
  const fs::SegmentStyle faint = fs::on_field_style(style, high, field, true);
  EXPECT_EQ(faint.colour.a, static_cast<int>(std::lround(fieldlines::palette::kAboveFieldOpacity * 255)));
  EXPECT_EQ(faint.colour.r, style.colour.r);
  EXPECT_EQ(faint.stroke, style.stroke);
  EXPECT_EQ(fs::on_field_style(style, high, field, false).colour, style.colour);
  EXPECT_EQ(fs::on_field_style(style, high, fieldlines::FieldBoundary{}, true).colour, style.colour);
}
