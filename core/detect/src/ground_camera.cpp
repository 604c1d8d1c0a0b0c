#include "fieldlines/detect/ground_camera.hpp"

#include <cmath>
#include <numbers>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

void validate(const GroundCamera& c) {
  const double quarter = std::numbers::pi / 2;
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!(finite(c.fx) && finite(c.fy) && finite(c.cx) && finite(c.cy) && finite(c.pitch_rad) && finite(c.roll_rad) &&
        finite(c.height_m)))
    throw Error("camera: every value must be a finite number");
  if (!(c.fx > 0 && c.fy > 0)) throw Error("camera: the focal lengths fx and fy must be positive");
  if (!(c.height_m > 0)) throw Error("camera: the height above the turf must be positive");
  if (!(std::abs(c.pitch_rad) < quarter && std::abs(c.roll_rad) < quarter))
    throw Error("camera: pitch and roll must lie within (-90, 90) degrees");
}

GroundProjection::GroundProjection(const GroundCamera& camera, double pitch_offset, double roll_offset)
    : camera_(camera) {
  // The renderer's axes with yaw 0: forward along +x tipped down by the pitch, right along -y,
  // down = forward x right; the roll turns right and down about forward.
  const double cp = std::cos(camera.pitch_rad + pitch_offset), sp = std::sin(camera.pitch_rad + pitch_offset);
  const double cr = std::cos(camera.roll_rad + roll_offset), sr = std::sin(camera.roll_rad + roll_offset);
  const cv::Vec3d forward(cp, 0, -sp), right(0, -1, 0);
  const cv::Vec3d down = forward.cross(right);
  const cv::Vec3d x = cr * right + sr * down, y = -sr * right + cr * down;
  to_world_ = cv::Matx33d(x[0], y[0], forward[0], x[1], y[1], forward[1], x[2], y[2], forward[2]);
}

std::optional<cv::Point2d> GroundProjection::to_ground(double u, double v) const {
  const cv::Vec3d d = to_world_ * cv::Vec3d((u - camera_.cx) / camera_.fx, (v - camera_.cy) / camera_.fy, 1.0);
  if (!(d[2] < -1e-9)) return std::nullopt;  // at or above the horizon (or NaN)
  const double t = camera_.height_m / -d[2];
  return cv::Point2d(t * d[0], t * d[1]);
}

std::optional<cv::Point2d> GroundProjection::to_image(cv::Point2d ground) const {
  const cv::Vec3d c = to_world_.t() * cv::Vec3d(ground.x, ground.y, -camera_.height_m);
  if (!(c[2] > 1e-3)) return std::nullopt;
  return cv::Point2d(camera_.cx + camera_.fx * c[0] / c[2], camera_.cy + camera_.fy * c[1] / c[2]);
}

}  // namespace fieldlines
