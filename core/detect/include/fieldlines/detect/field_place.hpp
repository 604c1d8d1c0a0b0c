#pragma once
// Where the camera stands on the field and which way it looks, from a place on the field it
// knows: the centre circle, whose centre is the field's origin, and the halfway line through it,
// which is the field's y axis. Field frame as the synthetic fields and most teams' world models
// have it: metres, origin at the centre mark, x along the field's length, y to the left.
//
// From ground features (ground_features.hpp: the camera's pitch, roll and height known): the
// circle's centre gives the position, the halfway line's direction the heading, up to a half
// turn: the field is symmetric about its centre, so of the two places the one in the half the
// caller names is returned (x <= 0 by default: a robot at its own side of the centre).
#include <optional>

#include "fieldlines/detect/ground_features.hpp"

namespace fieldlines {

struct FieldPlace {
  double x_m = 0, y_m = 0;  // the camera's foot on the field
  double yaw_rad = 0;       // its heading: 0 along +x, counter-clockwise, in (-pi, pi]
  int halfway_pieces = 0;   // the ground segments that gave the halfway line
};

struct FieldPlaceParams {
  double max_line_offset_m = 0.3;  // a segment whose line passes this close to the circle's centre...
  double min_piece_m = 0.3;        // ...and at least this long is a piece of the halfway line
  bool negative_half = true;       // the place with x <= 0 (false: x >= 0)
};

// None when `ground` holds no centre circle or no piece of a line through its centre.
std::optional<FieldPlace> place_from_centre_circle(const GroundFeatures& ground, const FieldPlaceParams& params = {});

}  // namespace fieldlines
