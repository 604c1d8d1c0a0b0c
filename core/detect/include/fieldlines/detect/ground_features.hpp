#pragma once
// The field features on the ground, when the camera is known (ground_camera.hpp): what a robot
// localises on. Names follow ros-sports' soccer_vision_3d_msgs (MarkingSegment start / end,
// MarkingIntersection center / rays, MarkingEllipse center / diameter, FieldBoundary points), in
// metres in the ground frame of ground_camera.hpp: x ahead, y to the left, z up, from the
// camera's foot, turning with the camera (yaw is not known).
//
// Perspective is taken exactly, not as an affine map at one point: a junction's rays are the
// ground directions of its image rays at the junction (two points a pixel apart, both projected),
// and the centre circle is the circle through its image ellipse's points projected one by one
// (the image ellipse's centre is not the circle's). Points at or above the horizon, or farther
// than max_distance_m, are never projected: a marking is cut where it reaches them, a boundary
// point there is left out.
//
// Each point carries the covariance the camera's angle noise gives it (angle_sigma_deg on the
// pitch and on the roll, as B-Human weighs its percepts): a point far away moves most.
#include <array>
#include <vector>

#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/ground_camera.hpp"

namespace fieldlines {

struct GroundPoint {
  double x = 0, y = 0;                   // metres
  std::array<double, 3> covariance{};    // xx, xy, yy (m^2) from the pitch and roll noise
};

struct GroundMarkingSegment {  // MarkingSegment: a stripe's centre line on the turf
  GroundPoint start, end;
  double width = 0;  // the stripe's width across at its middle, metres
};

struct GroundIntersection {  // MarkingIntersection
  GroundPoint center;
  JunctionType type = JunctionType::L;
  int num_rays = 0;
  std::array<std::array<double, 2>, 4> rays{};  // unit ground directions (x, y) of its arms
  float confidence = 0;                          // as the image junction's
};

struct GroundEllipse {  // MarkingEllipse: the centre circle on the turf
  GroundPoint center;
  double diameter = 0;  // metres
  float confidence = 0;  // as the image ellipse's
};

struct GroundFeatures {
  std::vector<GroundMarkingSegment> segments;
  std::vector<GroundIntersection> intersections;
  std::vector<GroundEllipse> ellipses;
  std::vector<GroundPoint> field_boundary;  // left to right in the image
  void clear() {
    segments.clear();
    intersections.clear();
    ellipses.clear();
    field_boundary.clear();
  }
};

struct GroundFeatureParams {
  double angle_sigma_deg = 1.0;  // the pitch's and the roll's standard deviation
  double max_distance_m = 15;    // farther from the camera's foot: not projected
};
// Throws fieldlines::Error unless the sigma lies in [0, 10] degrees and the distance is positive.
void validate(const GroundFeatureParams& params);

// Whether a junction's arms meet square on the ground: every two of its rays' ground directions
// (as project_features() gives them) within `tolerance_deg` of a multiple of 90 degrees. False
// when its centre does not lie on the ground.
bool square_on_ground(const Intersection& junction, const GroundProjection& projection, double tolerance_deg);

// `image` (one frame's features, image pixels) on the ground through `camera`, into `out`
// (cleared first; its vectors keep their capacity, so a warm caller allocates nothing).
void project_features(const FieldFeatures& image, const GroundCamera& camera, const GroundFeatureParams& params,
                      GroundFeatures& out);

}  // namespace fieldlines
