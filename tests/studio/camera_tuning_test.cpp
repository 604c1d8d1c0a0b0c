// The Camera tab's geometry: the ground grid drawn over the frame lies where the camera puts the
// turf (and nowhere above its horizon), moves when the pitch is nudged, the top view's mapping
// round-trips, and squares the field's lines only with the right camera.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "fieldlines/data/palette.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/ground_features.hpp"
#include "gui/model/camera_tuning.hpp"

namespace fs = fieldlines::studio;
using fieldlines::GroundCamera;
using fieldlines::GroundProjection;

namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr int kWidth = 640, kHeight = 480;

GroundCamera camera(double pitch_deg, double roll_deg = 0, double height_m = 0.6) {
  return fs::with_pose(fs::typical_camera(kWidth, kHeight), {pitch_deg, roll_deg, height_m * 100});
}

double distance_to_line(cv::Point2d p, const fs::GridLine& l) {
  const cv::Point2d d = l.b - l.a;
  const double t = std::clamp((p - l.a).dot(d) / d.dot(d), 0.0, 1.0);
  return cv::norm(p - (l.a + t * d));
}

double nearest_line(const fs::GroundGrid& grid, cv::Point2d p) {
  double best = std::numeric_limits<double>::infinity();
  for (const fs::GridLine& l : grid.lines) best = std::min(best, distance_to_line(p, l));
  return best;
}

// Whole multiples of `step` (metres), within a tenth of a millimetre.
bool on_step(double metres, double step) { return std::abs(metres / step - std::round(metres / step)) * step < 1e-4; }

}  // namespace

TEST(CameraTuning, GridLinesLieWhereTheProjectionPutsTheGroundPoints) {
  const GroundCamera cam = camera(30, 2);
  const GroundProjection projection(cam);
  const fs::GridParams params;  // 0.5 m, 8 m ahead, 4 m to either side
  fs::GroundGrid grid;
  fs::build_ground_grid(cam, kWidth, kHeight, params, grid);
  ASSERT_GT(grid.lines.size(), 10u);
  // Each piece's ends lie back on one grid line of the turf: both at x = k step, or both at y = k step.
  for (const fs::GridLine& l : grid.lines) {
    const auto a = projection.to_ground(l.a.x, l.a.y), b = projection.to_ground(l.b.x, l.b.y);
    ASSERT_TRUE(a && b);
    const bool across = on_step(a->x, params.step_m) && std::abs(a->x - b->x) < 1e-4;
    const bool along = on_step(a->y, params.step_m) && std::abs(a->y - b->y) < 1e-4;
    EXPECT_TRUE(across || along) << "(" << a->x << ", " << a->y << ") - (" << b->x << ", " << b->y << ")";
  }
  // And the crossings the camera sees are on the grid's image lines.
  int seen = 0;
  for (const cv::Point2d ground : {cv::Point2d{1.5, 0}, cv::Point2d{2, 0.5}, cv::Point2d{3, -1}, cv::Point2d{5, 1.5}}) {
    const auto px = projection.to_image(ground);
    ASSERT_TRUE(px);
    if (px->x < 0 || px->x > kWidth - 1 || px->y < 0 || px->y > kHeight - 1) continue;
    ++seen;
    EXPECT_LT(nearest_line(grid, *px), 1e-6) << ground;
  }
  EXPECT_GE(seen, 3);
  // A point between the lines is on none.
  EXPECT_GT(nearest_line(grid, *projection.to_image({2.25, 0.25})), 3);
}

TEST(CameraTuning, NothingIsDrawnAboveTheHorizon) {
  const GroundCamera cam = camera(8, 4);  // the horizon crosses the image
  const GroundProjection projection(cam);
  fs::GroundGrid grid;
  fs::build_ground_grid(cam, kWidth, kHeight, {0.5, 40, 20}, grid);  // lines far enough to reach it
  ASSERT_TRUE(grid.horizon);
  ASSERT_FALSE(grid.lines.empty());
  const fs::GridLine h = *grid.horizon;
  // The horizon: the turf ends there (a pixel below sees it, a pixel above does not).
  const cv::Point2d mid = 0.5 * (h.a + h.b);
  EXPECT_TRUE(projection.to_ground(mid.x, mid.y + 1));
  EXPECT_FALSE(projection.to_ground(mid.x, mid.y - 1));
  const auto side = [&](cv::Point2d p) { return (h.b - h.a).cross(p - h.a); };
  const double below = side({kWidth / 2.0, kHeight - 1.0});
  for (const fs::GridLine& l : grid.lines) {
    for (const cv::Point2d p : {l.a, l.b}) {
      EXPECT_TRUE(projection.to_ground(p.x, p.y)) << p;
      EXPECT_GT(side(p) * below, 0) << p;
      EXPECT_GE(p.x, -0.5 - 1e-9);
      EXPECT_LE(p.x, kWidth - 0.5 + 1e-9);
      EXPECT_GE(p.y, -0.5 - 1e-9);
      EXPECT_LE(p.y, kHeight - 0.5 + 1e-9);
    }
  }
  // Looking up: no turf in the image, no grid, no horizon in it.
  fs::build_ground_grid(camera(-60), kWidth, kHeight, {}, grid);
  EXPECT_TRUE(grid.lines.empty());
  EXPECT_FALSE(grid.horizon);
}

TEST(CameraTuning, NudgingThePitchMovesTheGrid) {
  GroundCamera cam = camera(30);
  fs::GroundGrid before, after;
  fs::build_ground_grid(cam, kWidth, kHeight, {}, before);
  fs::CameraPose pose = fs::pose_of(cam);
  for (int click = 0; click < 20; ++click) pose.pitch_deg += fs::kAngleStepDeg;  // 1 degree down
  cam = fs::with_pose(cam, pose);
  EXPECT_NEAR(cam.pitch_rad / kDeg, 31, 1e-9);
  fs::build_ground_grid(cam, kWidth, kHeight, {}, after);
  // The point 2 m ahead rises in the image (the camera looks further down) by about f * 1 degree,
  // and the new grid passes through its new place, not its old one.
  const auto old_px = GroundProjection(camera(30)).to_image({2, 0});
  const auto new_px = GroundProjection(cam).to_image({2, 0});
  ASSERT_TRUE(old_px && new_px);
  EXPECT_LT(new_px->y, old_px->y - 8);
  EXPECT_LT(nearest_line(after, *new_px), 1e-6);
  EXPECT_LT(nearest_line(before, *old_px), 1e-6);
  EXPECT_GT(distance_to_line(*old_px, after.lines[0]) + distance_to_line(*new_px, before.lines[0]), 0);
  bool moved = before.lines.size() != after.lines.size();
  for (std::size_t i = 0; !moved && i < before.lines.size(); ++i) moved = cv::norm(before.lines[i].a - after.lines[i].a) > 1;
  EXPECT_TRUE(moved);
}

TEST(CameraTuning, ThePoseIsNudgedWithinItsLimits) {
  const GroundCamera cam = camera(30, 1, 0.6);
  const fs::CameraPose pose = fs::pose_of(cam);
  EXPECT_NEAR(pose.pitch_deg, 30, 1e-9);
  EXPECT_NEAR(pose.roll_deg, 1, 1e-9);
  EXPECT_NEAR(pose.height_cm, 60, 1e-9);
  const GroundCamera wild = fs::with_pose(cam, {120, -95, 0});
  EXPECT_NEAR(wild.pitch_rad / kDeg, fs::kMaxAngleDeg, 1e-9);
  EXPECT_NEAR(wild.roll_rad / kDeg, -fs::kMaxAngleDeg, 1e-9);
  EXPECT_NEAR(wild.height_m, 0.01, 1e-12);
  EXPECT_NO_THROW(fieldlines::validate(wild));
  const GroundCamera kept = fs::with_pose(cam, {std::nan(""), HUGE_VAL, 75});
  EXPECT_EQ(kept.pitch_rad, cam.pitch_rad);
  EXPECT_EQ(kept.roll_rad, cam.roll_rad);
  EXPECT_NEAR(kept.height_m, 0.75, 1e-12);
  EXPECT_EQ(kept.fx, cam.fx);
}

TEST(CameraTuning, ATypicalCameraForASizeIsValidAndSeesTheTurf) {
  const GroundCamera c = fs::typical_camera(kWidth, kHeight);
  EXPECT_NO_THROW(fieldlines::validate(c));
  EXPECT_EQ(c.fx, kWidth);
  EXPECT_EQ(c.fy, kWidth);
  EXPECT_EQ(c.cx, 319.5);
  EXPECT_EQ(c.cy, 239.5);
  EXPECT_NEAR(c.pitch_rad / kDeg, 30, 1e-9);
  EXPECT_EQ(c.roll_rad, 0);
  EXPECT_EQ(c.height_m, 0.6);
  const auto centre = GroundProjection(c).to_ground(c.cx, c.cy);  // 0.6 m / tan 30 deg ahead
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 0.6 / std::tan(30 * kDeg), 1e-9);
  EXPECT_THROW(fs::typical_camera(0, 480), fieldlines::Error);
  EXPECT_TRUE(fs::intrinsics_note(c, kWidth, kHeight).empty());
  EXPECT_NE(fs::intrinsics_note(c, 200, 150).find("outside this 200x150 image"), std::string::npos);
}

TEST(CameraTuning, TheTopViewMappingRoundTrips) {
  const fs::TopView view({{10, 20}, {410, 280}}, 6);
  EXPECT_NEAR(view.pixels_per_metre(), 200 / 6.0, 1e-4);  // half the width limits it (the height: 248)
  EXPECT_NEAR(fs::TopView({{0, 0}, {400, 112}}, 5).pixels_per_metre(), 100 / 5.0, 1e-4);  // the height does
  const fs::Vec2 foot = view.to_panel({0, 0});
  EXPECT_FLOAT_EQ(foot.x, 210);
  EXPECT_FLOAT_EQ(foot.y, 280 - 12);
  EXPECT_LT(view.to_panel({1, 0}).y, foot.y);   // ahead is up
  EXPECT_LT(view.to_panel({0, 1}).x, foot.x);   // left is left
  for (const cv::Point2d g : {cv::Point2d{0, 0}, cv::Point2d{3.25, -1.5}, cv::Point2d{5.9, 2.7}}) {
    const cv::Point2d back = view.to_ground(view.to_panel(g));
    EXPECT_NEAR(back.x, g.x, 1e-4);
    EXPECT_NEAR(back.y, g.y, 1e-4);
  }
  const fs::Vec2 p{123.5f, 45.25f};
  const fs::Vec2 again = view.to_panel(view.to_ground(p));
  EXPECT_NEAR(again.x, p.x, 1e-3);
  EXPECT_NEAR(again.y, p.y, 1e-3);
}

namespace {

// The angle (degrees, 0..90) between the top view's first two feature lines.
double drawn_angle(const fs::TopViewDrawing& d) {
  std::vector<fs::Vec2> dirs;
  const fs::Rgba feature{fieldlines::palette::kFeature.r, fieldlines::palette::kFeature.g, fieldlines::palette::kFeature.b, 255};
  for (const fs::TopViewLine& l : d.lines)
    if (l.colour == feature && l.thickness == 2) dirs.push_back(l.b - l.a);
  EXPECT_EQ(dirs.size(), 2u);
  if (dirs.size() < 2) return 0;
  const double a = std::atan2(dirs[0].y, dirs[0].x) - std::atan2(dirs[1].y, dirs[1].x);
  return std::abs(std::remainder(a, std::numbers::pi)) / kDeg;
}

}  // namespace

TEST(CameraTuning, TheTopViewSquaresTheFieldsLinesOnlyWithTheRightCamera) {
  // Two painted lines meeting square on the turf, 2 m and 3 m ahead, seen by the true camera.
  const GroundCamera truth = camera(25, -2);
  const GroundProjection seen(truth);
  fieldlines::FieldFeatures image;
  const auto marking = [&](cv::Point2d a, cv::Point2d b) {
    const auto pa = seen.to_image(a), pb = seen.to_image(b);
    image.markings.push_back({static_cast<float>(pa->x), static_cast<float>(pa->y), static_cast<float>(pb->x),
                              static_cast<float>(pb->y), 4});
  };
  marking({2, -1.5}, {2, 1.5});
  marking({2, 1}, {5, 1});
  const fs::TopView view({{0, 0}, {380, 240}}, 6);
  fieldlines::GroundFeatures ground;
  fs::TopViewDrawing drawing;
  fieldlines::project_features(image, truth, {}, ground);
  fs::build_top_view(ground, truth, kWidth, kHeight, view, drawing);
  EXPECT_NEAR(drawn_angle(drawing), 90, 0.2);
  // The metre grid, the field of view and the camera's foot are drawn too.
  EXPECT_GT(drawing.lines.size(), 10u);
  ASSERT_FALSE(drawing.circles.empty());
  // Three degrees of pitch off: the lines fan out from square.
  const GroundCamera off = camera(28, -2);
  fieldlines::project_features(image, off, {}, ground);
  fs::build_top_view(ground, off, kWidth, kHeight, view, drawing);
  EXPECT_LT(drawn_angle(drawing), 88);
}

// One step per nudge, along its axis only; the None axis moves nothing.
TEST(CameraNudge, MovesOneStepAlongItsAxis) {
  const fs::CameraPose pose{30, 1, 60};
  const fs::CameraPose down = fs::nudged(pose, {fs::CameraAxis::Pitch, 1});
  EXPECT_DOUBLE_EQ(down.pitch_deg, 30 + fs::kAngleStepDeg);
  EXPECT_DOUBLE_EQ(down.roll_deg, 1);
  EXPECT_DOUBLE_EQ(down.height_cm, 60);
  EXPECT_DOUBLE_EQ(fs::nudged(pose, {fs::CameraAxis::Roll, -1}).roll_deg, 1 - fs::kAngleStepDeg);
  const fs::CameraPose lower = fs::nudged(pose, {fs::CameraAxis::Height, -1});
  EXPECT_DOUBLE_EQ(lower.height_cm, 60 - fs::kHeightStepCm);
  EXPECT_DOUBLE_EQ(lower.pitch_deg, 30);
  const fs::CameraPose same = fs::nudged(pose, {fs::CameraAxis::None, 1});
  EXPECT_DOUBLE_EQ(same.pitch_deg, 30);
  EXPECT_DOUBLE_EQ(same.roll_deg, 1);
  EXPECT_DOUBLE_EQ(same.height_cm, 60);
}
