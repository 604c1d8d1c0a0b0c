#pragma once
// The painted field: league dimensions and the lines as straight strips and circular arcs.
//
// Field frame: metres, origin at the centre mark, x along the field's length (towards the
// "+x" goal), y across it, z up. The ground (carpet) is the plane z = 0.
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace fieldlines::synth {

enum class Scene { Ssl, Kid };
std::string_view to_string(Scene scene);
// "ssl" or "kid"; throws fieldlines::Error otherwise.
Scene parse_scene(std::string_view text);

// One painted line: a straight strip (a -> b) or an arc of a circle, `width` metres wide.
struct PaintedLine {
  bool arc = false;
  Eigen::Vector2d a{0, 0}, b{0, 0};  // straight: centreline endpoints
  Eigen::Vector2d centre{0, 0};      // arc: circle centre, radius, start angle, sweep (rad)
  double radius = 0, start = 0, sweep = 0;
  double width = 0.01;
  std::string name;

  double length() const;
  bool full_circle() const;                 // an arc of the whole turn (the centre circle)
  Eigen::Vector2d point(double s) const;    // s in [0, length()]
  Eigen::Vector2d tangent(double s) const;  // unit
  // Distance from p to the centreline; `normal` gets the unit direction from the centreline
  // towards p (any unit normal when p is on it).
  double distance(const Eigen::Vector2d& p, Eigen::Vector2d& normal) const;
};

struct FieldParams {
  Scene scene = Scene::Ssl;
  double line_width = 0;    // metres; 0 = the league's rule (SSL 0.010, Kid 0.050)
  double wall_height = 0.15;  // SSL boundary wall (the rules ask for at least 0.10 m)
};

struct FieldModel {
  Scene scene = Scene::Ssl;
  double length = 9, width = 6;  // outer edges of the touch and goal lines' centrelines
  double runoff = 0.3;           // carpet beyond the lines
  double line_width = 0.01;
  double wall_height = 0;        // 0: no boundary wall (Kid size)
  double wall_thickness = 0.05;
  double goal_width = 1.0, goal_depth = 0.18, goal_height = 0.16;
  std::vector<PaintedLine> lines;

  double carpet_half_x() const { return length / 2 + runoff; }
  double carpet_half_y() const { return width / 2 + runoff; }
  bool on_carpet(double x, double y) const;
};

// Throws fieldlines::Error on a line width outside (0, 0.3] m or a negative wall height.
FieldModel make_field(const FieldParams& params);

// The radius of the field's centre circle (its full-turn arc), metres; 0 when it has none.
double centre_circle_radius(const FieldModel& field);

}  // namespace fieldlines::synth
