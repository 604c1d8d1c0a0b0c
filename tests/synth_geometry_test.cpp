// Geometry of the synthetic renderer: projection, ray casting, occlusion, and that the ground
// truth agrees with the rendered label mask.
#include <cmath>

#include <gtest/gtest.h>

#include "fieldlines/synth/synth.hpp"

namespace fieldlines::synth {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Camera test_camera(double pitch_deg, double roll_deg = 0) {
  Pose pose;
  pose.position = {0, 0, 0.2};
  pose.pitch = pitch_deg * kDeg;
  pose.roll = roll_deg * kDeg;
  return Camera(Intrinsics{}, pose);
}

TEST(SynthGeometry, FieldCornerProjectsWhereThePinholeModelSays) {
  const Camera cam = test_camera(10);
  const double th = 10 * kDeg;
  // Camera looking along +x from (0, 0, 0.2): right = -y, forward = (cos, 0, -sin), down = f x r.
  const Eigen::Vector3d d(4.5, 3.0, -0.2);  // corner (4.5, 3, 0) minus the camera centre
  const double zc = d.x() * std::cos(th) - d.z() * std::sin(th);
  const double xc = -d.y();
  const double yc = -d.x() * std::sin(th) - d.z() * std::cos(th);
  const auto px = cam.project({4.5, 3.0, 0});
  ASSERT_TRUE(px.has_value());
  EXPECT_NEAR(px->x(), 319.5 + 640 * xc / zc, 1e-9);
  EXPECT_NEAR(px->y(), 239.5 + 640 * yc / zc, 1e-9);
  EXPECT_LT(px->x(), 319.5);  // +y is to the left when looking along +x
  EXPECT_GT(px->y(), 239.5 - 640 * std::tan(th));  // the ground is below the horizon
}

TEST(SynthGeometry, PointsBehindTheCameraDoNotProject) {
  const Camera cam = test_camera(10);
  EXPECT_FALSE(cam.project({-1, 0, 0}).has_value());
}

TEST(SynthGeometry, RollRotatesTheImageAboutThePrincipalPoint) {
  const Eigen::Vector3d p(3, 1, 0);
  const auto a = test_camera(10, 0).project(p), b = test_camera(10, 7).project(p);
  ASSERT_TRUE(a && b);
  const Eigen::Vector2d c(319.5, 239.5), da = *a - c, db = *b - c;
  EXPECT_NEAR(da.norm(), db.norm(), 1e-9);
  const double turn = std::atan2(db.y(), db.x()) - std::atan2(da.y(), da.x());
  EXPECT_NEAR(std::abs(std::remainder(turn, 2 * 3.14159265358979323846)), 7 * kDeg, 1e-9);
}

TEST(SynthGeometry, RayThroughAProjectedCornerHitsTheGroundAtTheCorner) {
  World w;
  w.field = make_field({});
  const Camera cam = test_camera(12);
  for (const Eigen::Vector3d& corner : {Eigen::Vector3d(4.5, 3, 0), Eigen::Vector3d(4.5, -3, 0)}) {
    const auto px = cam.project(corner);
    ASSERT_TRUE(px.has_value());
    const Hit hit = cast(w, cam.centre(), cam.ray(px->x(), px->y()));
    EXPECT_EQ(hit.surface, Surface::Carpet);
    EXPECT_NEAR((hit.point - corner).norm(), 0, 1e-9);
  }
}

TEST(SynthGeometry, AnObjectOccludesTheLineBehindItInTruthAndMask) {
  World w;
  w.field = make_field({});
  const Camera cam = test_camera(8);
  // Without clutter the goal line +x (x = 4.5) crosses the whole view in one piece.
  auto visible_pieces = [&](const World& world) {
    int pieces = 0;
    for (const TruthFeature& f : extract_features(world, cam))
      if (f.name == "goal line +x") ++pieces;
    return pieces;
  };
  EXPECT_EQ(visible_pieces(w), 1);
  // A box on the camera's axis, between it and the goal line, hides the middle of the line.
  w.objects.push_back(Object::box({2.0, -0.2, 0}, {2.2, 0.2, 0.5}, Colour(30, 30, 30)));
  EXPECT_EQ(visible_pieces(w), 2);
  const auto hidden = cam.project({4.5, 0, 0});
  ASSERT_TRUE(hidden.has_value());
  for (const TruthFeature& f : extract_features(w, cam))
    for (const TruthPoint& p : f.points)
      if (f.name == "goal line +x") {
        EXPECT_GT(std::abs(p.x - hidden->x()), 5.0);
      }
  const Lighting light;
  const Rendered r = render(w, cam, light);
  EXPECT_EQ(r.mask.at<std::uint8_t>(static_cast<int>(std::lround(hidden->y())),
                                    static_cast<int>(std::lround(hidden->x()))),
            kMaskObject);
}

TEST(SynthGeometry, SslHasAWallBoundaryAndKidHasNone) {
  for (const Scene scene : {Scene::Ssl, Scene::Kid}) {
    SynthParams p;
    p.field.scene = scene;
    int boundaries = 0;
    for (int i = 0; i < 6; ++i)
      for (const TruthFeature& f : generate(p, 5, i).truth.features) boundaries += f.label == Label::Boundary;
    if (scene == Scene::Ssl)
      EXPECT_GT(boundaries, 0);
    else
      EXPECT_EQ(boundaries, 0);
  }
}

// Walks each truth polyline in 1-pixel steps and checks the mask around it.
struct Agreement {
  int checked = 0, agreed = 0;
};

Agreement check_truth_against_mask(const SynthSample& s) {
  Agreement a;
  auto mask_near = [&](double x, double y, int radius, std::uint8_t value) {
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const int u = static_cast<int>(std::lround(x)) + dx, v = static_cast<int>(std::lround(y)) + dy;
        if (u >= 0 && v >= 0 && u < s.mask.cols && v < s.mask.rows && s.mask.at<std::uint8_t>(v, u) == value)
          return true;
      }
    return false;
  };
  for (const TruthFeature& f : s.truth.features) {
    for (std::size_t i = 1; i < f.points.size(); ++i) {
      const TruthPoint& p = f.points[i - 1];
      const TruthPoint& q = f.points[i];
      const double len = std::hypot(q.x - p.x, q.y - p.y);
      for (double t = 0; t < len; t += 1.0) {
        const double k = t / len, x = p.x + k * (q.x - p.x), y = p.y + k * (q.y - p.y);
        const double width = p.width + k * (q.width - p.width);
        if (f.label == Label::Marking) {
          if (width < 2.0) continue;  // thinner lines never reach 50% coverage everywhere
          ++a.checked;
          a.agreed += mask_near(x, y, 1, kMaskPaint);
        } else {
          ++a.checked;
          a.agreed += mask_near(x, y, 2, kMaskFieldWall) &&
                      (mask_near(x, y, 2, kMaskCarpet) || mask_near(x, y, 2, kMaskPaint));
        }
      }
    }
  }
  return a;
}

TEST(SynthTruth, PolylinesLieOnThePaintAndTheWallFootInTheMask) {
  for (const Scene scene : {Scene::Ssl, Scene::Kid}) {
    SynthParams p;
    p.field.scene = scene;
    p.field.line_width = 0.05;
    Agreement total;
    for (int i = 0; i < 6; ++i) {
      const Agreement a = check_truth_against_mask(generate(p, 11, i));
      total.checked += a.checked;
      total.agreed += a.agreed;
    }
    ASSERT_GT(total.checked, 500) << to_string(scene);
    EXPECT_GE(static_cast<double>(total.agreed) / total.checked, 0.98) << to_string(scene);
  }
}

TEST(SynthTruth, WidthsGrowTowardsTheCamera) {
  // The halfway line seen from the side: the near end is wider in the image than the far end.
  World w;
  w.field = make_field({});
  Pose pose;
  pose.position = {-1.5, -3.2, 0.25};
  pose.yaw = 45 * kDeg;
  pose.pitch = 12 * kDeg;
  const Camera cam(Intrinsics{}, pose);
  bool found = false;
  for (const TruthFeature& f : extract_features(w, cam)) {
    if (f.name != "halfway line") continue;
    found = true;
    EXPECT_GT(f.points.front().width, f.points.back().width);  // drawn from y = -3 (near) to +3
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace fieldlines::synth
