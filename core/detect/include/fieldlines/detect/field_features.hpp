#pragma once
// What the detector finds on the field beyond labelled edge segments, in one result that a
// LineDetector owns and refills on each detect() (vectors keep their capacity: no allocation
// once warm). Names and conventions follow ros-sports' soccer_vision_2d_msgs: image pixels,
// x right, y down.
#include <vector>

namespace fieldlines {

// The centre line of a painted line (MarkingSegment): its two endpoints and its width across,
// in pixels.
struct Marking {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  float width = 0;
};

struct FieldFeatures {
  std::vector<Marking> markings;  // stripes (stripes.hpp); empty when the stage is off
  void clear() { markings.clear(); }
};

}  // namespace fieldlines
