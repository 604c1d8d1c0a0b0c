#pragma once
// The camera over a flat field: image pixels to points on the turf and back.
//
// A robot knows its camera: the intrinsics from calibration, the pitch, roll and height from
// its kinematics (or a fixed mount). With them a feature of known size on the turf (the centre
// circle) is fitted where it is a circle, three unknowns, rather than as an image conic, five,
// which a partly seen arc does not determine. Yaw does not matter: ground points are in a frame
// that turns with the camera (x ahead, y to the left, metres from the camera's foot).
//
// The pose follows the synthetic renderer (fieldlines::synth::Camera): pitch turns the optical
// axis down from the horizontal, roll turns the image about it (clockwise on screen for a
// positive roll).
#include <optional>

#include <opencv2/core/matx.hpp>
#include <opencv2/core/types.hpp>

namespace fieldlines {

struct GroundCamera {
  double fx = 0, fy = 0, cx = 0, cy = 0;  // pinhole intrinsics, px
  double pitch_rad = 0, roll_rad = 0;     // the optical axis below the horizontal; about it
  double height_m = 0;                    // the optical centre above the turf
};

// Throws fieldlines::Error unless every value is finite, fx, fy and the height are positive and
// the pitch and roll lie within (-90, 90) degrees.
void validate(const GroundCamera& camera);

class GroundProjection {
 public:
  // `camera` turned by `pitch_offset` and `roll_offset` (radians): the fit corrects a pose a
  // little off.
  explicit GroundProjection(const GroundCamera& camera, double pitch_offset = 0, double roll_offset = 0);
  // The turf point seen at pixel (u, v); none at or above the horizon.
  std::optional<cv::Point2d> to_ground(double u, double v) const;
  // The pixel a turf point is seen at; none behind the camera (or within a millimetre of its plane).
  std::optional<cv::Point2d> to_image(cv::Point2d ground) const;

 private:
  GroundCamera camera_;
  cv::Matx33d to_world_;  // camera axes (x right, y down, z forward) in the turf's (z up)
};

}  // namespace fieldlines
