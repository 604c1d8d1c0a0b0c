// fit_camera (camera_fit.hpp) on line sets made by projecting a Kid-size field's painted lines
// through a known camera, with noise on the ends and widths and chords of the centre circle
// among them (detections that are no straight lines): the pitch, roll and height come back from
// a start several degrees off; bad input is refused with a message.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/field.hpp"
#include "fieldlines/train/camera_fit.hpp"
#include "fieldlines/train/random.hpp"

namespace fl = fieldlines;
namespace synth = fieldlines::synth;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

struct Mount {
  double pitch_deg = 25, roll_deg = 2, height_m = 0.6;
};

struct Noise {
  double end_px = 0.5;     // sd of each end's position
  double width = 0.03;     // sd of the width, relative
};

synth::Intrinsics intrinsics() { return {}; }  // 640 x 480, f 640

// The visible piece of a ground polyline through `camera`: the longest run of its samples that
// lands inside the image, as image points.
std::vector<Eigen::Vector2d> visible_run(const synth::Camera& camera, const std::vector<Eigen::Vector2d>& ground) {
  const synth::Intrinsics& k = camera.intrinsics();
  std::vector<Eigen::Vector2d> best, run;
  for (const Eigen::Vector2d& g : ground) {
    const auto p = camera.project({g.x(), g.y(), 0});
    const bool in = p && p->x() >= 0 && p->x() <= k.width - 1 && p->y() >= 0 && p->y() <= k.height - 1 &&
                    camera.to_camera({g.x(), g.y(), 0}).z() > 0.2;
    if (in) run.push_back(*p);
    if (!in || &g == &ground.back()) {
      if (run.size() > best.size()) best = run;
      run.clear();
    }
  }
  return best;
}

// The width in px across the image line at ground point `g` on a line of ground direction `t`.
double image_width(const synth::Camera& camera, const Eigen::Vector2d& g, const Eigen::Vector2d& t, double width) {
  const Eigen::Vector2d n(-t.y(), t.x());
  const auto a = camera.project({g.x() + n.x() * width / 2, g.y() + n.y() * width / 2, 0});
  const auto b = camera.project({g.x() - n.x() * width / 2, g.y() - n.y() * width / 2, 0});
  const auto p0 = camera.project({g.x() - t.x(), g.y() - t.y(), 0});
  const auto p1 = camera.project({g.x() + t.x(), g.y() + t.y(), 0});
  if (!a || !b || !p0 || !p1) return 0;
  const Eigen::Vector2d d = (*p1 - *p0).normalized(), across = *a - *b;
  return std::abs(d.x() * across.y() - d.y() * across.x());
}

fl::Marking marking(Eigen::Vector2d p0, Eigen::Vector2d p1, double width, fl::Rand& rand, const Noise& noise) {
  p0 += Eigen::Vector2d(rand.normal(0, noise.end_px), rand.normal(0, noise.end_px));
  p1 += Eigen::Vector2d(rand.normal(0, noise.end_px), rand.normal(0, noise.end_px));
  const double w = width * (1 + rand.normal(0, noise.width));
  return {static_cast<float>(p0.x()), static_cast<float>(p0.y()), static_cast<float>(p1.x()),
          static_cast<float>(p1.y()), static_cast<float>(w)};
}

// What a detector would see of `field` through `camera`: each straight line's visible piece, and
// the centre circle's visible arc as chords of about half a metre.
fl::FrameLines frame_lines(const synth::FieldModel& field, const synth::Camera& camera, fl::Rand& rand,
                           const Noise& noise) {
  fl::FrameLines frame;
  frame.width = camera.intrinsics().width;
  frame.height = camera.intrinsics().height;
  for (const synth::PaintedLine& line : field.lines) {
    std::vector<Eigen::Vector2d> ground;
    const int n = 400;
    for (int i = 0; i <= n; ++i) ground.push_back(line.point(line.length() * i / n));
    const std::vector<Eigen::Vector2d> run = visible_run(camera, ground);
    if (run.size() < 2) continue;
    if (!line.arc) {
      if ((run.back() - run.front()).norm() < 20) continue;
      // The width where the piece's middle lies on the turf (found again by projecting it).
      const auto at = [&](const Eigen::Vector2d& p) {
        const Eigen::Vector3d r = camera.ray(p.x(), p.y());
        const double t = -camera.centre().z() / r.z();
        return Eigen::Vector2d(camera.centre().x() + t * r.x(), camera.centre().y() + t * r.y());
      };
      const Eigen::Vector2d middle = at((run.front() + run.back()) / 2);
      const double w = image_width(camera, middle, (line.b - line.a).normalized(), line.width);
      frame.markings.push_back(marking(run.front(), run.back(), w, rand, noise));
    } else {
      const std::size_t step = 22;  // samples of about 0.17 m on a 0.75 m circle: chords of 0.5 m
      for (std::size_t i = 0; i + step < run.size(); i += step)
        if ((run[i + step] - run[i]).norm() >= 20) frame.markings.push_back(marking(run[i], run[i + step], 4, rand, noise));
    }
  }
  return frame;
}

// `n` frames of one camera mount: positions and headings differ, each frame shows two lines or
// more.
std::vector<fl::FrameLines> frames_of(const Mount& mount, int n, std::uint64_t seed, const Noise& noise = {}) {
  const synth::FieldModel field = synth::make_field({.scene = synth::Scene::Kid});
  fl::Rand rand(seed);
  std::vector<fl::FrameLines> frames;
  while (static_cast<int>(frames.size()) < n) {
    synth::Pose pose;
    pose.position = {rand.uniform(-field.length / 2, field.length / 2), rand.uniform(-field.width / 2, field.width / 2),
                     mount.height_m};
    pose.yaw = rand.uniform(-std::numbers::pi, std::numbers::pi);
    pose.pitch = mount.pitch_deg * kDeg;
    pose.roll = mount.roll_deg * kDeg;
    fl::FrameLines f = frame_lines(field, synth::Camera(intrinsics(), pose), rand, noise);
    if (f.markings.size() >= 2) frames.push_back(std::move(f));
  }
  return frames;
}

// A 640 x 480 frame holding `markings`.
fl::FrameLines frame_of(std::vector<fl::Marking> markings) {
  fl::FrameLines f;
  f.markings = std::move(markings);
  f.width = 640, f.height = 480;
  return f;
}

fl::GroundCamera camera_of(const Mount& m) {
  const synth::Intrinsics k = intrinsics();
  return {.fx = k.fx, .fy = k.fy, .cx = k.cx, .cy = k.cy, .pitch_rad = m.pitch_deg * kDeg,
          .roll_rad = m.roll_deg * kDeg, .height_m = m.height_m};
}

// The message fit_camera throws, or "" when it does not.
std::string thrown(const std::vector<fl::FrameLines>& frames, const fl::GroundCamera& start,
                   const fl::CameraFitParams& params = {}) {
  try {
    fl::fit_camera(frames, start, params);
  } catch (const fl::Error& e) {
    return e.what();
  }
  return "";
}

struct Case {
  Mount truth;
  double pitch_off_deg, roll_off_deg;
};

const Case kCases[] = {
    {{25, 2, 0.6}, 5, -5},  {{40, -3, 0.8}, -5, 5}, {{15, 0, 0.45}, 4, 3},
    {{30, 5, 0.7}, -3, -4}, {{20, -1, 0.5}, 5, 5},  {{35, 1, 0.9}, -5, -5},
};

TEST(CameraFit, RecoversPitchAndRollFromFiveDegreesOff) {
  std::uint64_t seed = 901;
  for (const Case& c : kCases) {
    const auto frames = frames_of(c.truth, 10, seed++);
    fl::GroundCamera start = camera_of(c.truth);
    start.pitch_rad += c.pitch_off_deg * kDeg;
    start.roll_rad += c.roll_off_deg * kDeg;
    const fl::CameraFit fit = fl::fit_camera(frames, start);
    const std::string what = "truth pitch " + std::to_string(c.truth.pitch_deg) + " roll " + std::to_string(c.truth.roll_deg);
    EXPECT_NEAR(fit.camera.pitch_rad / kDeg, c.truth.pitch_deg, 0.3) << what;
    EXPECT_NEAR(fit.camera.roll_rad / kDeg, c.truth.roll_deg, 0.3) << what;
    EXPECT_DOUBLE_EQ(fit.camera.height_m, start.height_m) << "no line width: the start's height is kept";
    EXPECT_FALSE(fit.height_fitted);
    EXPECT_LT(fit.rms_after_deg, 1.0) << what;
    EXPECT_GT(fit.fitting_share, 0.8) << what;
    EXPECT_GT(fit.rms_before_deg, 2 * fit.rms_after_deg) << what;
    EXPECT_GE(fit.frames_used, 8) << what;
    EXPECT_GE(fit.lines_used, 20) << what;
    // The start's focal length is right: the fit leaves it within a percent.
    EXPECT_NEAR(fit.focal_scale, 1, 0.01) << what;
    EXPECT_DOUBLE_EQ(fit.camera.fx, start.fx * fit.focal_scale);
    EXPECT_EQ(fit.camera.cx, start.cx);
  }
}

TEST(CameraFit, FocalLengthKeptWhenItsSdIsZero) {
  const Case& c = kCases[0];
  const auto frames = frames_of(c.truth, 10, 907);
  fl::GroundCamera start = camera_of(c.truth);
  start.pitch_rad += c.pitch_off_deg * kDeg;
  start.fx *= 1.02, start.fy *= 1.02;
  fl::CameraFitParams kept;
  kept.focal_sd = 0;
  const fl::CameraFit fit = fl::fit_camera(frames, start, kept);
  EXPECT_EQ(fit.camera.fx, start.fx);
  EXPECT_EQ(fit.camera.fy, start.fy);
  EXPECT_EQ(fit.focal_scale, 1);
}

// The fit's own sd decides: a set whose pose sd is above max_pose_sd_deg is refused, naming it.
TEST(CameraFit, APoseTheLinesDoNotPinDownIsRefused) {
  const Case& c = kCases[2];
  const auto frames = frames_of(c.truth, 4, 911);
  fl::GroundCamera start = camera_of(c.truth);
  start.pitch_rad += c.pitch_off_deg * kDeg;
  const auto at_most = [](double sd) {
    fl::CameraFitParams params;
    params.max_pose_sd_deg = sd;
    return params;
  };
  const fl::CameraFit fit = fl::fit_camera(frames, start, at_most(5));
  const double sd = std::max(fit.pitch_sd_deg, fit.roll_sd_deg);
  ASSERT_GT(sd, 0);
  EXPECT_NO_THROW(fl::fit_camera(frames, start, at_most(1.1 * sd)));
  const std::string message = thrown(frames, start, at_most(0.9 * sd));
  EXPECT_NE(message.find("do not pin the pose down"), std::string::npos) << message;
}

TEST(CameraFit, HeightFromTheLineWidth) {
  std::uint64_t seed = 921;
  for (const Case& c : kCases) {
    const auto frames = frames_of(c.truth, 10, seed++);
    fl::GroundCamera start = camera_of(c.truth);
    start.pitch_rad += c.pitch_off_deg * kDeg;
    start.roll_rad += c.roll_off_deg * kDeg;
    start.height_m = c.truth.height_m * (c.pitch_off_deg > 0 ? 1.25 : 0.8);
    const fl::CameraFit fit = fl::fit_camera(frames, start, {.line_width_m = 0.05});
    EXPECT_TRUE(fit.height_fitted);
    EXPECT_NEAR(fit.camera.height_m, c.truth.height_m, 0.03) << "truth pitch " << c.truth.pitch_deg;
    EXPECT_GT(fit.widths_used, 10);
  }
}

// The downward angle of the ray through pixel (u, v) under `camera`.
double ray_pitch_deg(const fl::GroundCamera& camera, double u, double v) {
  const synth::Intrinsics k{.width = 640, .height = 480, .fx = camera.fx, .fy = camera.fy, .cx = camera.cx, .cy = camera.cy};
  const Eigen::Vector3d d = synth::Camera(k, {.position = {0, 0, camera.height_m}, .yaw = 0, .pitch = camera.pitch_rad,
                                              .roll = camera.roll_rad}).ray(u, v);
  return std::atan2(-d.z(), d.head<2>().norm()) / kDeg;
}

// With the intrinsics a little off, no pose gives the true rays: the fitted pitch takes up the
// principal point's error (5 px are 0.45 degrees at f 640), so the measure is the ray through
// the true principal point, which the fitted camera must aim where the true one does.
TEST(CameraFit, IntrinsicsAFewPercentOff) {
  std::uint64_t seed = 941;
  double focal_error = 0;
  for (const Case& c : kCases) {
    const auto frames = frames_of(c.truth, 10, seed++);
    const fl::GroundCamera truth = camera_of(c.truth);
    fl::GroundCamera start = truth;
    start.pitch_rad += c.pitch_off_deg * kDeg;
    start.roll_rad += c.roll_off_deg * kDeg;
    start.fx *= 1.02, start.fy *= 1.02, start.cx += 5, start.cy -= 5;
    const fl::CameraFit fit = fl::fit_camera(frames, start, {.line_width_m = 0.05});
    const std::string what = "truth pitch " + std::to_string(c.truth.pitch_deg);
    EXPECT_NEAR(ray_pitch_deg(fit.camera, truth.cx, truth.cy), c.truth.pitch_deg, 0.3) << what;
    EXPECT_NEAR(fit.camera.roll_rad / kDeg, c.truth.roll_deg, 0.3) << what;
    EXPECT_NEAR(fit.camera.height_m, c.truth.height_m, 0.03) << what;
    focal_error += std::abs(fit.camera.fx / truth.fx - 1) / std::size(kCases);
  }
  EXPECT_LT(focal_error, 0.015) << "the focal lengths 2 % off: the fit brings them nearer the truth";
}

TEST(CameraFit, NoLinesIsRefused) {
  std::vector<fl::FrameLines> frames(3, frame_of({}));
  const std::string message = thrown(frames, camera_of({}));
  EXPECT_NE(message.find("no lines"), std::string::npos) << message;
  // One line alone (or lines of one direction) cannot be fitted either.
  frames[0].markings = {{100, 400, 300, 420, 5}, {110, 300, 310, 320, 5}};
  const std::string one_direction = thrown(frames, camera_of({}));
  EXPECT_NE(one_direction.find("2 lines in 2 directions"), std::string::npos) << one_direction;
  // Lines of one or two frames: poses far apart may square them alike.
  const auto two = frames_of({}, 2, 963);
  const std::string few_frames = thrown(two, camera_of({}));
  EXPECT_NE(few_frames.find("too few frames with lines"), std::string::npos) << few_frames;
}

TEST(CameraFit, LinesAboveTheHorizonAreRefused) {
  // A camera nearly level: its horizon is near the middle row, and these lines are above it.
  std::vector<fl::FrameLines> frames(2, frame_of({{100, 20, 400, 40, 3}, {200, 10, 210, 120, 3}}));
  const std::string message = thrown(frames, camera_of({.pitch_deg = 2, .roll_deg = 0, .height_m = 0.6}));
  EXPECT_NE(message.find("above the start camera's horizon"), std::string::npos) << message;
}

TEST(CameraFit, ACameraLookingAboveTheHorizonIsRefused) {
  const auto frames = frames_of({}, 3, 961);
  const std::string message = thrown(frames, camera_of({.pitch_deg = -60, .roll_deg = 0, .height_m = 0.6}));
  EXPECT_NE(message.find("sees no ground"), std::string::npos) << message;
}

TEST(CameraFit, ContradictoryFramesAreRefused) {
  // Half the frames from a camera pitched 15 degrees and rolled 8, half from one pitched 40 and
  // rolled -8: no one pose puts both halves' lines square.
  auto frames = frames_of({15, 8, 0.6}, 5, 971);
  for (auto& f : frames_of({40, -8, 0.6}, 5, 972)) frames.push_back(std::move(f));
  const std::string message = thrown(frames, camera_of({28, 0, 0.6}));
  EXPECT_NE(message.find("contradict"), std::string::npos) << message;
  // Lines at random angles: no field at all.
  fl::Rand rand(973);
  std::vector<fl::FrameLines> random(6, frame_of({}));
  for (auto& f : random)
    for (int i = 0; i < 8; ++i) {
      const double x = rand.uniform(100, 540), y = rand.uniform(300, 460), a = rand.uniform(0, std::numbers::pi);
      f.markings.push_back({static_cast<float>(x), static_cast<float>(y), static_cast<float>(x + 80 * std::cos(a)),
                            static_cast<float>(y + 80 * std::sin(a)), 4});
    }
  const std::string noise = thrown(random, camera_of({}));
  EXPECT_NE(noise.find("contradict"), std::string::npos) << noise;
}

TEST(CameraFit, BadParametersAreRefused) {
  const auto frames = frames_of({}, 3, 981);
  EXPECT_NE(thrown(frames, camera_of({}), {.line_width_m = std::nan("")}).find("line width"), std::string::npos);
  EXPECT_NE(thrown(frames, camera_of({}), {.line_width_m = 3}).find("line width"), std::string::npos);
  EXPECT_NE(thrown({}, camera_of({})).find("no frames"), std::string::npos);
  fl::GroundCamera bad = camera_of({});
  bad.fx = 0;
  EXPECT_NE(thrown(frames, bad).find("focal"), std::string::npos);
  fl::CameraFitParams negative;
  negative.focal_sd = -0.01;
  EXPECT_NE(thrown(frames, camera_of({}), negative).find("focal_sd"), std::string::npos);
}

}  // namespace
