// The field boundary (fieldlines/detect/field_boundary.hpp): where the green ends, robust to a
// robot standing on the field and a wide line near the camera; empty without a field; and the
// gate it puts on both classes.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "cli_test_support.hpp"
#include "painted_field.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/light.hpp"
#include "fieldlines/detect/turf_colours.hpp"
#include "fieldlines/synth/synth.hpp"

namespace fl = fieldlines;

namespace {

// Carpet below a tilted horizon (y 100 at the left, 140 at the right), grey hall above.
cv::Mat field_frame() {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(120, 120, 120));
  const std::vector<cv::Point> carpet{{0, 100}, {639, 140}, {639, 479}, {0, 479}};
  cv::fillConvexPoly(img, carpet, cv::Scalar(50, 140, 40));
  return img;
}

float horizon(float x) { return 100 + 40 * x / 639; }

// Column x of `img` painted `colour` from `from` px above the carpet's edge up to `to` px above it.
void above_the_edge(cv::Mat& img, int x, int from, int to, const cv::Scalar& colour) {
  const int edge = static_cast<int>(std::lround(horizon(float(x))));
  cv::line(img, {x, edge - to}, {x, edge - from - 1}, colour);
}

// The boundary of `img` (noise added) under `params`, checked to run along `edge` left of `right`.
fl::FieldBoundary expect_along(cv::Mat& img, float (*edge)(float), float right,
                               const fl::FieldBoundaryParams& params = {}) {
  img = fl::test::noisy(img);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, b, params);
  EXPECT_FALSE(b.empty());
  for (float x = 0; x < right; x += 16) EXPECT_NEAR(b.y_at(x), edge(x), 4) << "x " << x;
  return b;
}

// ...along the carpet's edge, all the way.
fl::FieldBoundary expect_along_the_edge(cv::Mat& img, const fl::FieldBoundaryParams& params = {}) {
  return expect_along(img, horizon, 640, params);
}

TEST(FieldBoundary, FollowsTheTopOfTheGreenPastRobotsAndWideLines) {
  cv::Mat img = field_frame();
  // A black robot standing on the field hides the green up to y 300 over 80 columns, and a
  // 60 px wide white line crosses the left part near the camera.
  cv::rectangle(img, {300, 90}, {380, 300}, cv::Scalar(15, 15, 15), cv::FILLED);
  cv::line(img, {0, 300}, {200, 330}, cv::Scalar(250, 250, 250), 60);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, b);
  ASSERT_FALSE(b.empty());
  for (float x = 0; x < 640; x += 16) EXPECT_NEAR(b.y_at(x), horizon(x), 4) << "x " << x;
  EXPECT_EQ(b.image_height, 480);
}

// A robot at the frame's side hides the field's far edge down to row 400: the hull's end would
// fall from the field's edge to the robot's foot; it is held level instead.
TEST(FieldBoundary, ARobotAtTheSideDoesNotPullTheEndDown) {
  cv::Mat img = field_frame();
  cv::rectangle(img, {560, 80}, {639, 400}, cv::Scalar(15, 15, 15), cv::FILLED);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, b);
  ASSERT_FALSE(b.empty());
  for (float x = 0; x < 560; x += 16) EXPECT_NEAR(b.y_at(x), horizon(x), 4) << "x " << x;
  // Beyond the robot: level with the last column seen, not down at its foot.
  EXPECT_NEAR(b.y_at(620), horizon(552), 6);
}

// Robots near the camera at the frame's right side stand on the turf from row 190 to 400: the
// columns' scans end at their feet, and held level the boundary would lie 14 px above the
// field's edge at the right. The turf above them, longer than the gap and no higher than the
// rest of the edge, is the field's (MSL Bordeaux: a robot at a fisheye frame's side).
TEST(FieldBoundary, TheTurfAboveARobotAtTheSideIsTheFields) {
  cv::Mat img = field_frame();
  cv::rectangle(img, {400, 190}, {639, 400}, cv::Scalar(15, 15, 15), cv::FILLED);
  const fl::FieldBoundary b = expect_along_the_edge(img);
  ASSERT_FALSE(b.empty());
  fl::FieldBoundaryParams stop_at_the_robot;
  stop_at_the_robot.past_occluder_run = 0;
  fl::FieldBoundary held;
  fl::find_field_boundary(img, held, stop_at_the_robot);
  EXPECT_LT(held.y_at(620), horizon(620) - 8) << "without looking past the robot the boundary is held level";
}

// The robots hide the field's edge up to row 60 instead, and a green poster hangs in the hall
// from row 10 to 50 above them: the first field past them lies far higher than the rest of the
// boundary, so it is not the field's.
TEST(FieldBoundary, AGreenPosterAboveARobotAtTheSideIsNotTheField) {
  cv::Mat img = field_frame();
  cv::rectangle(img, {400, 60}, {639, 400}, cv::Scalar(15, 15, 15), cv::FILLED);
  cv::rectangle(img, {400, 10}, {639, 50}, cv::Scalar(50, 140, 40), cv::FILLED);
  fl::FieldBoundary b = expect_along(img, horizon, 400);
  ASSERT_FALSE(b.empty());
  EXPECT_GT(b.y_at(620), 90) << "the poster is no top";
  fl::FieldBoundaryParams any_rise;
  any_rise.past_occluder_rise = 10;
  fl::find_field_boundary(img, b, any_rise);
  EXPECT_LT(b.y_at(620), 60) << "without the rise's limit the poster is the field";
}

// The field's edge 5 px under the frame's top (the camera tilted down), and a robot at the side
// reaching from row 400 past the top: its columns find no turf above it, and half a gap above the
// highest point lies above the frame. The look past it must still end.
TEST(FieldBoundary, ARobotReachingTheFramesTopEndsTheLookPastIt) {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(50, 140, 40));
  cv::rectangle(img, {0, 0}, {639, 4}, cv::Scalar(120, 120, 120), cv::FILLED);
  cv::rectangle(img, {400, 0}, {639, 400}, cv::Scalar(15, 15, 15), cv::FILLED);
  expect_along(img, [](float) { return 5.f; }, 400);
}

// A robot's sloping shoulder at the frame's left side (MSL Bordeaux, fisheye): it hides the
// far edge down a slope of 0.9 rows per column, gentler than a wall's side but steeper than a
// field's corner falls away. Its hull end is dropped and the boundary held level.
namespace {
// The carpet with a robot's dark shoulder over its left 90 columns, falling from row 102 at
// column 90 to row `bottom` at the frame's side (noise added).
cv::Mat with_shoulder(int bottom) {
  cv::Mat img = field_frame();
  const std::vector<cv::Point> shoulder{{0, 60}, {90, 60}, {90, 102}, {0, bottom}};
  cv::fillConvexPoly(img, shoulder, cv::Scalar(15, 15, 15));
  return fl::test::noisy(img);
}
}  // namespace

TEST(FieldBoundary, ARobotsSlopingShoulderAtTheSideIsNoFieldCorner) {
  const cv::Mat img = with_shoulder(183);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, b);
  ASSERT_FALSE(b.empty());
  for (float x = 96; x < 640; x += 16) EXPECT_NEAR(b.y_at(x), horizon(x), 4) << "x " << x;
  EXPECT_NEAR(b.y_at(0), horizon(96), 6) << "level with the first column seen, not down the shoulder";
}

// A gentler shoulder, 0.7 rows per column (MSL Bordeaux `_104852`), is a shoulder too when it
// falls by more than the gap; a field's edge whose last columns at the frame's side fall as
// steeply, by less than the gap (a synthetic field's far edge at a frame's corner), is kept.
TEST(FieldBoundary, AGentleShoulderFallsFurtherThanAFieldsEdge) {
  const cv::Mat img = with_shoulder(165);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, b);
  ASSERT_FALSE(b.empty());
  EXPECT_NEAR(b.y_at(0), horizon(96), 6) << "level with the first column seen, not down the shoulder";
  fl::FieldBoundaryParams no_shoulders;
  no_shoulders.shoulder_fall = 100;
  fl::find_field_boundary(img, b, no_shoulders);
  EXPECT_GT(b.y_at(0), horizon(96) + 30) << "dropping only ends steeper than 0.75 follows the shoulder down";

  // The far edge falls by 25 px over the last 40 columns on the right, less than the gap (29 px).
  // Rows sampled one by one: with the default two, an 8-column piece's slope is a multiple of 0.25.
  cv::Mat edge = field_frame();
  const std::vector<cv::Point> corner{{600, 100}, {639, 100}, {639, 163}, {600, 138}};
  cv::fillConvexPoly(edge, corner, cv::Scalar(120, 120, 120));
  edge = fl::test::noisy(edge);
  fl::FieldBoundaryParams fine;
  fine.row_step = 1;
  fl::find_field_boundary(edge, b, fine);
  ASSERT_FALSE(b.empty());
  EXPECT_GT(b.y_at(636), 155) << "the field's edge falling at the side is kept";
  fl::FieldBoundaryParams any_fall = fine;
  any_fall.shoulder_fall = 0;
  fl::find_field_boundary(edge, b, any_fall);
  EXPECT_LT(b.y_at(636), 154) << "dropping every end steeper than 0.6 cuts the field's edge";
}

// A dark wall along the field, shorter than the gap a ball may leave, with a green curtain 40 px
// tall above it (the authors' SSL lab): the curtain is not the field, although the
// scan crosses the wall to reach it; field less than twice the wall's length above a band that
// long does not pay for it, and the top settles at the field's edge.
TEST(FieldBoundary, AGreenCurtainAboveAWallIsNotTheField) {
  cv::Mat img = field_frame();
  const int wall = 24;  // below the gap (6 % of 480 = 29 px) and above 0.8 of it
  for (int x = 0; x < 640; ++x) {
    above_the_edge(img, x, 0, wall, cv::Scalar(20, 20, 20));
    if (x < 240) above_the_edge(img, x, wall, wall + 40, cv::Scalar(50, 140, 40));
  }
  fl::FieldBoundary b = expect_along_the_edge(img);
  fl::FieldBoundaryParams free_bands;
  free_bands.band_cost = 0;
  fl::find_field_boundary(img, b, free_bands);
  EXPECT_LT(b.y_at(100), horizon(100) - wall) << "without the band's cost the curtain is the field";
}

// A light floor strip 24 px tall between this field and the next one behind it, whose turf
// shows 40 px tall between the legs of people standing on the strip (Humanoid, Montreal): the
// strip reads as paint, which never ends the field, so the scan crosses it. A band with paint
// in it half the gap long costs as a bare one: the turf beyond does not pay for it, and the
// top settles at this field's edge. Without that rule the next field is taken for this one.
TEST(FieldBoundary, AFloorStripBeforeTheNextFieldIsNotTheField) {
  cv::Mat img = field_frame();
  const int strip = 24, next = 40;
  for (int x = 0; x < 640; ++x) {
    above_the_edge(img, x, 0, strip, cv::Scalar(200, 205, 210));
    const bool leg = x % 80 < 30;
    above_the_edge(img, x, strip, strip + next, leg ? cv::Scalar(40, 40, 60) : cv::Scalar(50, 140, 40));
  }
  fl::FieldBoundary b = expect_along_the_edge(img);
  fl::FieldBoundaryParams paint_free;
  paint_free.paint_band_fraction = 10;  // longer than any column: paint is never a band
  fl::find_field_boundary(img, b, paint_free);
  EXPECT_LT(b.y_at(320), horizon(320) - strip) << "without the rule the next field is this one";
}

// The same strip, but dark trousers and shoes on it and only a shoe's sliver of greenish turf
// (2 px) showing between them, the dark legs above (Humanoid, Montreal: the next field between
// people's legs): the scan crosses the strip, shorter than the gap, to that sliver; a lone run of
// field that short above a band without field half the gap long carries the scan on but is no
// top, so the boundary stays at this field's edge. Turf 8 px tall there is a top.
TEST(FieldBoundary, ALoneGreenSliverAboveAFloorStripIsNoTop) {
  const int strip = 20;
  const auto frame_with = [&](int turf) {
    cv::Mat img = field_frame();
    for (int x = 0; x < 640; ++x) {
      above_the_edge(img, x, 0, strip, cv::Scalar(60, 90, 130));  // a brown floor, too dark for paint
      above_the_edge(img, x, strip, strip + turf, cv::Scalar(50, 140, 40));
      above_the_edge(img, x, strip + turf, strip + turf + 60, cv::Scalar(30, 25, 25));
    }
    return img;
  };
  cv::Mat sliver = frame_with(2);
  expect_along_the_edge(sliver);
  fl::FieldBoundaryParams any_run;
  any_run.min_top_samples = 1;
  fl::FieldBoundary b;
  fl::find_field_boundary(sliver, b, any_run);
  EXPECT_LT(b.y_at(320), horizon(320) - strip) << "without the rule the sliver is the top";
  cv::Mat turf = fl::test::noisy(frame_with(8));
  fl::find_field_boundary(turf, b);
  EXPECT_NEAR(b.y_at(320), horizon(320) - strip - 8, 3) << "a run of turf is a top";
}

// A touchline 6 px wide right at the carpet's edge, the field's dark surround 10 px tall beyond
// it, the grey hall above (MSL Bordeaux: the far touchline with no turf beyond it in view): the
// boundary runs along the line's top, where the turf's edge is, not along its foot. Beside a
// light floor instead of the dark surround the line could as well be the floor's edge: the
// boundary stays at the turf, as it does when the paint is as wide as a floor strip.
TEST(FieldBoundary, ALineAlongTheTurfsEdgeIsTheFields) {
  const int line = 6;
  const auto boundary_with = [&](int paint, const cv::Scalar& beyond) {
    cv::Mat img = field_frame();
    for (int x = 0; x < 640; ++x) {
      above_the_edge(img, x, 0, paint, cv::Scalar(235, 240, 240));
      above_the_edge(img, x, paint, paint + 10, beyond);
    }
    img = fl::test::noisy(img);
    fl::FieldBoundary b;
    fl::find_field_boundary(img, b);
    EXPECT_FALSE(b.empty());
    return b;
  };
  const cv::Scalar dark(20, 20, 20), light_floor(190, 195, 200);
  const fl::FieldBoundary along = boundary_with(line, dark);
  for (float x = 0; x < 640; x += 16) EXPECT_NEAR(along.y_at(x), horizon(x) - line, 3) << "x " << x;
  const fl::FieldBoundary floor = boundary_with(line, light_floor);
  for (float x = 0; x < 640; x += 16) EXPECT_NEAR(floor.y_at(x), horizon(x), 3) << "beside a light floor, x " << x;
  const fl::FieldBoundary wide = boundary_with(24, dark);
  for (float x = 0; x < 640; x += 16) EXPECT_NEAR(wide.y_at(x), horizon(x), 3) << "24 px of paint, x " << x;
}

// A line 20 px wide across the frame a few rows below its top, with turf above it up to the
// frame's edge (a camera looking down near a line): nothing above the frame is seen, so the
// few rows of turf there do not have to pay for the line, and the line stays on the field.
TEST(FieldBoundary, AWideLineUnderTheFramesTopStaysOnTheField) {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(50, 140, 40));
  cv::rectangle(img, {0, 6}, {639, 25}, cv::Scalar(245, 245, 245), cv::FILLED);
  img = fl::test::noisy(img);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, b);
  ASSERT_FALSE(b.empty());
  for (float x = 0; x < 640; x += 16) EXPECT_LT(b.y_at(x), 4) << "x " << x;
}

// A band of the field's surround along its edge (MSL Bangkok: a darker carpet strip), 0.065 in
// chromaticity from the turf: within the median's loose tolerance, outside the turf colours the
// frame measures. With them the boundary keeps to the turf's edge; with the loose tolerance it
// runs along the band's top. (No pixel noise: it would blur a colour difference this small.)
TEST(FieldBoundary, TheFieldsSurroundIsNotTurfWhenTheTurfColoursAreMeasured) {
  cv::Mat img = field_frame();
  const int band = 10;
  for (int x = 0; x < 640; ++x) above_the_edge(img, x, 0, band, cv::Scalar(64, 124, 40));
  const std::optional<fl::Rgb> field = fl::estimate_field_colour(img);
  ASSERT_TRUE(field);
  fl::TurfColours turf;
  turf.measure(img, *field);
  fl::FieldBoundary b;
  fl::find_field_boundary(img, *field, b, {}, &turf);
  ASSERT_FALSE(b.empty());
  for (float x = 0; x < 640; x += 16) EXPECT_NEAR(b.y_at(x), horizon(x), 4) << "x " << x;
  fl::FieldBoundaryParams loose;
  loose.turf_chroma_tolerance = loose.chroma_tolerance;
  fl::find_field_boundary(img, *field, b, loose, &turf);
  EXPECT_LT(b.y_at(320), horizon(320) - band + 4) << "the loose tolerance takes the band for turf";
}

// A sunlit field with the shade of a window on it: the far part of the right third lies in warm
// sun (a chromaticity 0.12 from the shade's median), its near part in the shade. With the
// median's colour alone those columns end at the sun patch's lower edge, and the boundary runs
// down to the right; the frame's own turf colours (turf_colours.hpp) hold it at the field's edge.
TEST(FieldBoundary, SunAndShadeOnTheFieldKeepTheBoundaryAtItsEdge) {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(120, 120, 120));
  const cv::Vec3f shade(60, 110, 50), sun(60, 210, 120);  // B, G, R
  for (int y = 150; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      // The sun patch x >= 430, y < 330, with a soft edge (a penumbra) 40 px wide.
      const float in_x = std::clamp((float(x) - 410.f) / 40.f, 0.f, 1.f), in_y = std::clamp((350.f - float(y)) / 40.f, 0.f, 1.f);
      const cv::Vec3f c = shade + (sun - shade) * (in_x * in_y);
      img.at<cv::Vec3b>(y, x) = {cv::saturate_cast<std::uint8_t>(c[0]), cv::saturate_cast<std::uint8_t>(c[1]),
                                 cv::saturate_cast<std::uint8_t>(c[2])};
    }
  img = fl::test::noisy(img);
  const std::optional<fl::Rgb> field = fl::estimate_field_colour(img);
  ASSERT_TRUE(field);
  fl::TurfColours turf;
  turf.measure(img, *field);
  // Every hull end kept as it falls: the turf colours alone hold the sunlit side up.
  fl::FieldBoundaryParams keep_ends;
  keep_ends.max_end_slope = keep_ends.shoulder_slope = 1000;
  fl::FieldBoundary one_colour, turf_colours;
  fl::find_field_boundary(img, *field, one_colour, keep_ends);
  fl::find_field_boundary(img, *field, turf_colours, keep_ends, &turf);
  int right = 0, right_one_colour = 0;
  for (int x = 0; x < 640; x += 8) {
    right += std::abs(turf_colours.y_at(float(x)) - 150) <= 4;
    right_one_colour += std::abs(one_colour.y_at(float(x)) - 150) <= 4;
  }
  EXPECT_EQ(right, 80) << "every column at the field's edge";
  EXPECT_LT(right_one_colour, 70) << "the median's colour alone loses the sunlit columns";
}

// The turf at the field's far edge seen through a goal's net (Humanoid frame2150): above the
// carpet's edge its colour drifts to a paler green (0.095 of chromaticity from the median, as
// saturated as 0.78 of it) and back over 48 px, the turf's far edge 8 px on. 26 px of it lie out
// of the field colour: the scan crosses them (shorter than the gap), and when the top settles
// they read as a band without field, which the 8 px beyond do not pay for. Followed sample by
// sample from the turf beyond (settle_chain_step), the drift is turf: the top stays at the far
// edge. Camera noise of sd 1.5: a net's shade is smooth.
TEST(FieldBoundary, TurfDriftingIntoAnotherLightStaysTheFields) {
  cv::Mat img = field_frame();
  const cv::Vec3f carpet(50, 140, 40), pale(65, 145, 55);  // B, G, R
  constexpr int kRamp = 16, kPlateau = 16, kBeyond = 8, kTurf = 2 * kRamp + kPlateau + kBeyond;
  for (int x = 0; x < 640; ++x)
    for (int h = 0; h < kTurf; ++h) {
      const float t = h < kRamp ? float(h) / kRamp : h < kRamp + kPlateau ? 1.f
                                                   : std::max(0.f, 1.f - float(h - kRamp - kPlateau) / kRamp);
      const cv::Vec3f c = carpet + (pale - carpet) * t;
      above_the_edge(img, x, h, h + 1, cv::Scalar(c[0], c[1], c[2]));
    }
  cv::Mat noise(img.size(), CV_16SC3), wide;
  cv::RNG(7).fill(noise, cv::RNG::NORMAL, 0, 1.5);
  img.convertTo(wide, CV_16SC3);
  wide += noise;
  wide.convertTo(img, CV_8UC3);
  fl::FieldBoundary chained, unchained;
  fl::find_field_boundary(img, chained);
  fl::FieldBoundaryParams off;
  off.settle_chain_step = 0;
  fl::find_field_boundary(img, unchained, off);
  for (float x = 0; x < 640; x += 16) EXPECT_NEAR(chained.y_at(x), horizon(x) - kTurf, 4) << "x " << x;
  EXPECT_GT(unchained.y_at(320), horizon(320) - kTurf + 30) << "without the chain the top settles below the drift";
}

// Skipping the samples between two field samples (max_jump) finds the tops that testing every
// sample finds: on synthetic fields in every light and on random clutter (turf, paint, dark and
// grey blocks, lines of every width, noise).
TEST(FieldBoundary, SkippingInsideTheFieldFindsTheSameTops) {
  std::vector<cv::Mat> frames;
  fl::synth::SynthParams p;
  p.conditions = {fl::synth::Condition::Natural, fl::synth::Condition::Shadows, fl::synth::Condition::Dim};
  for (const fl::synth::Scene scene : {fl::synth::Scene::Ssl, fl::synth::Scene::Kid}) {
    p.field.scene = scene;
    for (int i = 0; i < 6; ++i) frames.push_back(fl::synth::generate(p, 5, i).bgr);
  }
  cv::RNG rng(3);
  // Floor strips of several heights with a sliver of turf above them (a lone run: no top).
  cv::RNG strips(5);
  for (int i = 0; i < 4; ++i) {
    cv::Mat img = field_frame();
    const int strip = strips.uniform(8, 30), sliver = strips.uniform(2, 8);
    for (int x = 0; x < 640; ++x) {
      above_the_edge(img, x, 0, strip, cv::Scalar(60, 90, 130));
      above_the_edge(img, x, strip, strip + sliver, cv::Scalar(50, 140, 40));
      above_the_edge(img, x, strip + sliver, strip + sliver + 60, cv::Scalar(30, 25, 25));
    }
    frames.push_back(fl::test::noisy(img, 11 + i));
  }
  const cv::Scalar colours[] = {{50, 140, 40}, {250, 250, 250}, {15, 15, 15}, {120, 120, 120}, {60, 170, 50}};
  for (int i = 0; i < 80; ++i) {
    cv::Mat img(rng.uniform(40, 300), rng.uniform(40, 400), CV_8UC3, colours[0]);
    for (int k = 0; k < 12; ++k) {
      const cv::Point a(rng.uniform(0, img.cols), rng.uniform(0, img.rows)), b(rng.uniform(0, img.cols), rng.uniform(0, img.rows));
      const cv::Scalar& c = colours[rng.uniform(0, 5)];
      if (k % 2) cv::rectangle(img, a, b, c, cv::FILLED);
      else cv::line(img, a, b, c, rng.uniform(1, 30));
    }
    cv::Mat noise(img.size(), CV_8UC3);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 12);
    frames.push_back(img + noise);
  }
  int compared = 0;
  for (const cv::Mat& frame : frames) {
    const auto field = fl::estimate_field_colour(frame);
    if (!field) continue;
    fl::FieldBoundaryParams every;
    every.max_jump = 0;
    fl::FieldBoundary fast, slow;
    fl::find_field_boundary(frame, *field, fast);
    fl::find_field_boundary(frame, *field, slow, every);
    ASSERT_EQ(fast.columns.size(), slow.columns.size());
    for (std::size_t i = 0; i < fast.columns.size(); ++i) {
      EXPECT_EQ(fast.columns[i].x, slow.columns[i].x);
      EXPECT_EQ(fast.columns[i].y, slow.columns[i].y) << "frame " << compared << " column " << fast.columns[i].x;
    }
    compared += !slow.columns.empty();
  }
  EXPECT_GE(compared, 20);
}

TEST(FieldBoundary, EmptyWithoutAField) {
  fl::FieldBoundary b;
  fl::find_field_boundary(cv::Mat(480, 640, CV_8UC3, cv::Scalar(120, 120, 120)), b);
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.y_at(10), -1);
  fl::find_field_boundary(cv::Mat(), b);
  EXPECT_TRUE(b.empty());
  fl::find_field_boundary(cv::Mat(480, 640, CV_8UC1, cv::Scalar(100)), b);
  EXPECT_TRUE(b.empty());
}

TEST(FieldBoundary, GateDropsMarkingsAboveAndBoundaryEdgesAwayFromIt) {
  fl::FieldBoundary b;
  fl::find_field_boundary(field_frame(), b);
  ASSERT_FALSE(b.empty());
  const auto at = [](float y, fl::Label label) {
    fl::Segment s;
    s.x0 = 0, s.x1 = 40, s.y0 = s.y1 = y;
    s.label = label;
    return s;
  };
  EXPECT_EQ(fl::gate_by_field_boundary(at(50, fl::Label::Marking), b), fl::Label::None);
  EXPECT_EQ(fl::gate_by_field_boundary(at(300, fl::Label::Marking), b), fl::Label::Marking);
  EXPECT_EQ(fl::gate_by_field_boundary(at(102, fl::Label::Boundary), b), fl::Label::Boundary);
  EXPECT_EQ(fl::gate_by_field_boundary(at(300, fl::Label::Boundary), b), fl::Label::None);
  EXPECT_EQ(fl::gate_by_field_boundary(at(50, fl::Label::None), b), fl::Label::None);
  // An empty boundary gates nothing.
  EXPECT_EQ(fl::gate_by_field_boundary(at(50, fl::Label::Marking), fl::FieldBoundary{}), fl::Label::Marking);
}

TEST(FieldBoundary, DetectorFindsItWhenAskedAndGatesWithTheThresholds) {
  const cv::Mat img = fl::test::synthetic_field(640, 480);
  fl::LineDetector plain;
  plain.detect(img);
  EXPECT_TRUE(plain.field_boundary().empty()) << "not asked for: not computed";
  EXPECT_FALSE(plain.field_colour()) << "neither light nor boundary needed it";
  fl::Thresholds gated;
  gated.field_boundary_gate = true;
  fl::LineDetector detector({}, gated);
  const std::vector<fl::Segment> found = detector.detect(img);
  ASSERT_FALSE(detector.field_boundary().empty());
  ASSERT_TRUE(detector.field_colour());
  EXPECT_NEAR((*detector.field_colour())[1], 140, 4);  // the carpet's green, measured once
  // The synthetic wall's foot is at y 80-89; every marking lies below it.
  EXPECT_NEAR(detector.field_boundary().y_at(320), 85, 8);
  for (const fl::Segment& s : found) {
    if (s.label == fl::Label::Marking) {
      EXPECT_GT(0.5f * (s.y0 + s.y1), detector.field_boundary().y_at(0.5f * (s.x0 + s.x1)));
    }
  }
}

}  // namespace
