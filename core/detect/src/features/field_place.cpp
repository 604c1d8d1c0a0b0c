#include "fieldlines/detect/field_place.hpp"

#include <cmath>
#include <numbers>

namespace fieldlines {

std::optional<FieldPlace> place_from_centre_circle(const GroundFeatures& ground, const FieldPlaceParams& params) {
  if (ground.ellipses.empty()) return std::nullopt;
  // The most confident circle: a frame shows one centre circle.
  const GroundEllipse* circle = &ground.ellipses.front();
  for (const GroundEllipse& e : ground.ellipses)
    if (e.confidence > circle->confidence) circle = &e;
  const double cx = circle->center.x, cy = circle->center.y;
  // The halfway line's direction, up to a half turn: the length-weighted mean of the doubled
  // angles of the pieces whose lines pass through the centre (a direction and its opposite agree).
  double sum_c = 0, sum_s = 0;
  int pieces = 0;
  for (const GroundMarkingSegment& s : ground.segments) {
    const double dx = s.end.x - s.start.x, dy = s.end.y - s.start.y, length = std::hypot(dx, dy);
    if (!(length >= params.min_piece_m)) continue;
    const double offset = std::abs(dx * (cy - s.start.y) - dy * (cx - s.start.x)) / length;
    if (offset > params.max_line_offset_m) continue;
    const double a = 2 * std::atan2(dy, dx);
    sum_c += length * std::cos(a), sum_s += length * std::sin(a);
    ++pieces;
  }
  if (pieces == 0 || std::hypot(sum_c, sum_s) == 0) return std::nullopt;
  const double line = 0.5 * std::atan2(sum_s, sum_c);  // the field's y axis, in the ground frame
  // The field's x axis in the ground frame is the y axis turned a quarter clockwise; the
  // heading is the turn that takes it onto the field's (cos yaw, -sin yaw) = x axis.
  double yaw = -(line - std::numbers::pi / 2);
  // The camera's foot on the field: the circle's centre is the origin, so p = -R(yaw) c.
  const auto place = [&](double heading) {
    const double c = std::cos(heading), s = std::sin(heading);
    return FieldPlace{-(c * cx - s * cy), -(s * cx + c * cy), std::remainder(heading, 2 * std::numbers::pi), pieces};
  };
  FieldPlace p = place(yaw);
  if ((p.x_m > 0) == params.negative_half) p = place(yaw + std::numbers::pi);
  return p;
}

}  // namespace fieldlines
