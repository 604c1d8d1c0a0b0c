// Overlay colours against the pictures they are drawn on: turf of every league's lighting and
// white paint. Measured as CIE76 Delta-E (fixtures.hpp), the bound each colour must clear.
#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "gui/model/overlay_style.hpp"

namespace fs = fieldlines::studio;
using fieldlines::Label;

namespace {

std::array<int, 3> rgb(fs::Rgba c) { return {c.r, c.g, c.b}; }

// SSL carpet, a sunny Nao field, a dark artificial-turf field, a bleached sunny one, white paint.
constexpr std::array<std::array<int, 3>, 5> kBackgrounds{{{50, 140, 40}, {90, 180, 60}, {30, 90, 40}, {130, 200, 90}, {255, 255, 255}}};

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
