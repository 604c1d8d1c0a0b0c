#include "fieldlines/synth/camera.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::synth {
namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
}

GroundCamera to_ground_camera(const Intrinsics& k, const Pose& pose) {
  return {.fx = k.fx, .fy = k.fy, .cx = k.cx, .cy = k.cy, .pitch_rad = pose.pitch, .roll_rad = pose.roll,
          .height_m = pose.position.z()};
}

Camera::Camera(const Intrinsics& k, const Pose& pose) : k_(k), pose_(pose) {
  const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
  const double cp = std::cos(pose.pitch), sp = std::sin(pose.pitch);
  const Eigen::Vector3d forward(cp * cy, cp * sy, -sp);
  const Eigen::Vector3d right0(sy, -cy, 0);
  const Eigen::Vector3d down0 = forward.cross(right0);
  const double cr = std::cos(pose.roll), sr = std::sin(pose.roll);
  r_wc_.col(0) = cr * right0 + sr * down0;
  r_wc_.col(1) = -sr * right0 + cr * down0;
  r_wc_.col(2) = forward;
}

Eigen::Vector3d Camera::to_camera(const Eigen::Vector3d& world) const {
  return r_wc_.transpose() * (world - pose_.position);
}

std::optional<Eigen::Vector2d> Camera::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d c = to_camera(world);
  if (c.z() <= 1e-3) return std::nullopt;
  return Eigen::Vector2d(k_.cx + k_.fx * c.x() / c.z(), k_.cy + k_.fy * c.y() / c.z());
}

Eigen::Vector3d Camera::ray(double u, double v) const {
  return r_wc_ * Eigen::Vector3d((u - k_.cx) / k_.fx, (v - k_.cy) / k_.fy, 1.0);
}

CameraRanges default_camera_ranges(Scene scene) {
  CameraRanges r;
  if (scene == Scene::Kid) {
    r.height_min = 0.40, r.height_max = 0.90;
    r.pitch_min = 10, r.pitch_max = 45;
    r.roll_max = 6;
  }
  return r;
}

void validate(const CameraRanges& r) {
  auto check = [](bool ok, const std::string& what) {
    if (!ok) throw Error("camera ranges: " + what);
  };
  check(r.height_min > 0.01 && r.height_min <= r.height_max && r.height_max <= 5,
        "height must satisfy 0.01 < min <= max <= 5 m");
  check(r.pitch_min >= -30 && r.pitch_min <= r.pitch_max && r.pitch_max <= 89,
        "pitch must satisfy -30 <= min <= max <= 89 degrees");
  check(r.roll_max >= 0 && r.roll_max <= 45, "roll must be in [0, 45] degrees");
  check(!r.roll || (r.roll->first >= -45 && r.roll->first <= r.roll->second && r.roll->second <= 45),
        "roll must satisfy -45 <= min <= max <= 45 degrees");
  check(r.fx_min >= 50 && r.fx_min <= r.fx_max && r.fx_max <= 5000,
        "focal length must satisfy 50 <= min <= max <= 5000 px");
  check(r.aim_jitter >= 0 && r.aim_jitter <= 180, "aim jitter must be in [0, 180] degrees");
  check(r.min_carpet_fraction >= 0 && r.min_carpet_fraction <= 1,
        "min carpet fraction must be in [0, 1]");
}

double carpet_fraction(const Camera& camera, const FieldModel& field) {
  const Intrinsics& k = camera.intrinsics();
  int hits = 0, total = 0;
  for (int j = 0; j < 12; ++j) {
    for (int i = 0; i < 16; ++i) {
      const Eigen::Vector3d d = camera.ray((i + 0.5) * k.width / 16.0, (j + 0.5) * k.height / 12.0);
      ++total;
      if (d.z() >= 0) continue;
      const double t = -camera.centre().z() / d.z();
      const Eigen::Vector3d p = camera.centre() + t * d;
      if (field.on_carpet(p.x(), p.y())) ++hits;
    }
  }
  return static_cast<double>(hits) / total;
}

Camera sample_camera(const FieldModel& field, const Intrinsics& k, const CameraRanges& ranges,
                     Rand& rand) {
  validate(ranges);
  Camera best(k, Pose{});
  double best_fraction = -1;
  const double px = field.carpet_half_x() - 0.1, py = field.carpet_half_y() - 0.1;
  for (int attempt = 0; attempt < 64; ++attempt) {
    Pose pose;
    pose.position = {rand.uniform(-px, px), rand.uniform(-py, py),
                     rand.uniform(ranges.height_min, ranges.height_max)};
    // Aim at a point inside the lines, at least a metre away, so the field fills the view.
    Eigen::Vector2d target;
    do {
      target = {rand.uniform(-field.length / 2, field.length / 2),
                rand.uniform(-field.width / 2, field.width / 2)};
    } while ((target - pose.position.head<2>()).norm() < 1.0);
    const Eigen::Vector2d to = target - pose.position.head<2>();
    pose.yaw = std::atan2(to.y(), to.x()) + rand.uniform(-1, 1) * ranges.aim_jitter * kDeg;
    pose.pitch = rand.uniform(ranges.pitch_min, ranges.pitch_max) * kDeg;
    // One draw either way, so a range given keeps every other draw of the seed.
    pose.roll = (ranges.roll ? rand.uniform(ranges.roll->first, ranges.roll->second)
                             : rand.uniform(-1, 1) * ranges.roll_max) * kDeg;
    const double fx = rand.uniform(ranges.fx_min, ranges.fx_max);
    Intrinsics ki = k;
    ki.fx = ki.fy = fx;
    const Camera camera(ki, pose);
    const double fraction = carpet_fraction(camera, field);
    if (fraction > best_fraction) best_fraction = fraction, best = camera;
    if (fraction >= ranges.min_carpet_fraction) break;
  }
  return best;
}

}  // namespace fieldlines::synth
