#pragma once
// A robot's pinhole camera: intrinsics, pose in the field frame, projection and pixel rays.
//
// Pixel convention: integer (u, v) is the centre of a pixel, which covers [u-0.5, u+0.5].
// Camera frame: x right, y down, z forward (OpenCV). Pose angles: yaw is the heading in the
// field's xy plane (0 = looking along +x), pitch > 0 looks down, roll turns the image clockwise.
#include <optional>
#include <utility>

#include <Eigen/Core>

#include "fieldlines/detect/ground_camera.hpp"
#include "fieldlines/synth/field.hpp"
#include "fieldlines/train/random.hpp"

namespace fieldlines::synth {

struct Intrinsics {
  int width = 640, height = 480;
  double fx = 640, fy = 640;
  double cx = 319.5, cy = 239.5;
};

struct Pose {
  Eigen::Vector3d position{0, 0, 0.15};
  double yaw = 0, pitch = 0, roll = 0;  // radians
};

// The camera as the detector takes it (ground_camera.hpp): its intrinsics, pitch, roll and
// height above the turf.
GroundCamera to_ground_camera(const Intrinsics& k, const Pose& pose);

class Camera {
 public:
  Camera(const Intrinsics& k, const Pose& pose);

  const Intrinsics& intrinsics() const { return k_; }
  const Pose& pose() const { return pose_; }
  const Eigen::Vector3d& centre() const { return pose_.position; }
  const Eigen::Matrix3d& rotation() const { return r_wc_; }  // camera -> world

  // Point in camera coordinates.
  Eigen::Vector3d to_camera(const Eigen::Vector3d& world) const;
  // Pixel of a world point; nullopt when it is not in front of the camera (z <= 1 mm).
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world) const;
  // World direction of the ray through pixel (u, v), not normalised (camera z component 1).
  Eigen::Vector3d ray(double u, double v) const;

 private:
  Intrinsics k_;
  Pose pose_;
  Eigen::Matrix3d r_wc_;
};

// Where a robot's camera may be. Angles in degrees.
struct CameraRanges {
  double height_min = 0.12, height_max = 0.30;  // metres above the carpet
  double pitch_min = 2, pitch_max = 22;          // looking down
  double roll_max = 4;                           // |roll|
  // The roll drawn within [lo, hi] instead of +-roll_max: a camera on a fixed mount (lo = hi),
  // whose frames `fieldlines calibrate-camera` fits.
  std::optional<std::pair<double, double>> roll;
  double fx_min = 600, fx_max = 680;             // focal length in pixels (fy = fx)
  double aim_jitter = 25;                        // heading error from the aim point (deg)
  double min_carpet_fraction = 0.35;             // share of the image that must show carpet
};

// A robot-like default for each league: SSL robots are 15 cm tall, Kid-size humanoids 40-90 cm.
CameraRanges default_camera_ranges(Scene scene);
// Throws fieldlines::Error naming the field when a range is empty or out of bounds.
void validate(const CameraRanges& ranges);

// The fraction of a coarse grid of pixel rays that hit the carpet (no occlusion test).
double carpet_fraction(const Camera& camera, const FieldModel& field);

// A random camera (pose on the carpet aiming at a point of the field, focal length in range)
// with `k`'s image size, retried until at least `min_carpet_fraction` of the image is carpet
// (after 64 tries the best one is kept).
Camera sample_camera(const FieldModel& field, const Intrinsics& k, const CameraRanges& ranges,
                     Rand& rand);

}  // namespace fieldlines::synth
