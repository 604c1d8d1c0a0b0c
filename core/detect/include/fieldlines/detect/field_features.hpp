#pragma once
// What the detector finds on the field beyond labelled edge segments, in one result that a
// LineDetector owns and refills on each detect() (vectors keep their capacity: no allocation
// once warm). Names and conventions follow ros-sports' soccer_vision_2d_msgs: image pixels,
// x right, y down; headings in radians, 0 along +x, pi/2 along +y (image down).
#include <array>
#include <vector>

#include "fieldlines/detect/field_boundary.hpp"

namespace fieldlines {

// The centre line of a painted line (MarkingSegment): its two endpoints and its width across,
// in pixels.
struct Marking {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  float width = 0;
};

// Where painted lines meet (MarkingIntersection): an L has 2 rays, a T 3, an X 4. Each ray is
// the heading of one arm leaving the centre, ascending in [0, 2pi); only the first num_rays of
// heading_rays mean anything (a fixed array: no allocation per junction).
enum class JunctionType { L, T, X };
struct Intersection {
  float x = 0, y = 0;
  JunctionType type = JunctionType::L;
  int num_rays = 0;
  std::array<float, 4> heading_rays{};
  float confidence = 0;  // in [0, 1]: how long and how well-met its arms are
};

// An ellipse in the image (MarkingEllipse): centre, full axes along and across angle_deg
// (degrees, from +x towards +y), as cv::RotatedRect has them.
struct MarkingEllipse {
  float cx = 0, cy = 0, width = 0, height = 0, angle_deg = 0;
  float confidence = 0;  // in [0, 1]: the share of its arc the fitted points cover
};

struct FieldFeatures {
  std::vector<Marking> markings;            // stripes (stripes.hpp); empty when the stage is off
  std::vector<Intersection> intersections;  // intersections.hpp; empty when the stage is off
  std::vector<MarkingEllipse> ellipses;     // the centre circle (centre_circle.hpp); likewise
  FieldBoundary field_boundary;             // field_boundary.hpp; as LineDetector::field_boundary()
  void clear() {
    markings.clear();
    intersections.clear();
    ellipses.clear();
    field_boundary.clear();
  }
};

// "L", "T" or "X".
const char* to_string(JunctionType type);

}  // namespace fieldlines
