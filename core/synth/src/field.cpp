#include "fieldlines/synth/field.hpp"

#include <algorithm>
#include <cmath>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;

void add_segment(FieldModel& f, std::string name, Eigen::Vector2d a, Eigen::Vector2d b) {
  PaintedLine line;
  line.a = a;
  line.b = b;
  line.width = f.line_width;
  line.name = std::move(name);
  f.lines.push_back(std::move(line));
}

void add_circle(FieldModel& f, std::string name, Eigen::Vector2d centre, double radius) {
  PaintedLine line;
  line.arc = true;
  line.centre = centre;
  line.radius = radius;
  line.start = 0;
  line.sweep = 2 * kPi;
  line.width = f.line_width;
  line.name = std::move(name);
  f.lines.push_back(std::move(line));
}

// A rectangle open on the goal line side (defense, goal and penalty areas), for both goals.
void add_areas(FieldModel& f, const std::string& name, double depth, double breadth) {
  for (const double side : {-1.0, 1.0}) {
    const double gx = side * f.length / 2, ix = gx - side * depth, hy = breadth / 2;
    const std::string tag = name + (side > 0 ? " +x" : " -x");
    add_segment(f, tag + " front", {ix, -hy}, {ix, hy});
    add_segment(f, tag + " side -y", {gx, -hy}, {ix, -hy});
    add_segment(f, tag + " side +y", {gx, hy}, {ix, hy});
  }
}

// A cross of two strips, `size` metres long each (penalty and centre marks).
void add_mark(FieldModel& f, const std::string& name, Eigen::Vector2d c, double size) {
  const double h = size / 2;
  add_segment(f, name + " x", {c.x() - h, c.y()}, {c.x() + h, c.y()});
  add_segment(f, name + " y", {c.x(), c.y() - h}, {c.x(), c.y() + h});
}

}  // namespace

std::string_view to_string(Scene scene) { return scene == Scene::Ssl ? "ssl" : "kid"; }

Scene parse_scene(std::string_view text) {
  if (text == "ssl") return Scene::Ssl;
  if (text == "kid") return Scene::Kid;
  throw Error("unknown scene '" + std::string(text) + "' (expected ssl or kid)");
}

double PaintedLine::length() const { return arc ? radius * std::abs(sweep) : (b - a).norm(); }

bool PaintedLine::full_circle() const { return arc && std::abs(sweep) >= 2 * kPi - 1e-9; }

Eigen::Vector2d PaintedLine::point(double s) const {
  if (!arc) return a + (b - a) * (s / std::max(length(), 1e-12));
  const double ang = start + sweep * s / std::max(length(), 1e-12);
  return centre + radius * Eigen::Vector2d(std::cos(ang), std::sin(ang));
}

Eigen::Vector2d PaintedLine::tangent(double s) const {
  if (!arc) return (b - a).normalized();
  const double ang = start + sweep * s / std::max(length(), 1e-12);
  const double dir = sweep >= 0 ? 1.0 : -1.0;
  return dir * Eigen::Vector2d(-std::sin(ang), std::cos(ang));
}

double PaintedLine::distance(const Eigen::Vector2d& p, Eigen::Vector2d& normal) const {
  if (arc) {  // full circles only in the fields built here, so no angular clamp is needed
    const Eigen::Vector2d d = p - centre;
    const double r = d.norm();
    normal = r > 1e-12 ? Eigen::Vector2d(d / r) : Eigen::Vector2d(1, 0);
    const double dist = r - radius;
    if (dist < 0) normal = -normal;
    return std::abs(dist);
  }
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-24), 0.0, 1.0);
  const Eigen::Vector2d d = p - (a + t * ab);
  const double dist = d.norm();
  normal = dist > 1e-12 ? Eigen::Vector2d(d / dist) : Eigen::Vector2d(-ab.y(), ab.x()).normalized();
  return dist;
}

bool FieldModel::on_carpet(double x, double y) const {
  return std::abs(x) <= carpet_half_x() && std::abs(y) <= carpet_half_y();
}

FieldModel make_field(const FieldParams& params) {
  FieldModel f;
  f.scene = params.scene;
  const bool ssl = params.scene == Scene::Ssl;
  f.line_width = params.line_width > 0 ? params.line_width : (ssl ? 0.010 : 0.050);
  if (!(f.line_width > 0 && f.line_width <= 0.3))
    throw Error("line width must be in (0, 0.3] metres, got " + std::to_string(params.line_width));
  if (!(params.wall_height >= 0 && params.wall_height <= 2))
    throw Error("wall height must be in [0, 2] metres, got " + std::to_string(params.wall_height));
  f.length = 9;
  f.width = 6;
  f.runoff = ssl ? 0.3 : 1.0;
  f.wall_height = ssl ? params.wall_height : 0;
  if (ssl) {
    f.goal_width = 1.0, f.goal_depth = 0.18, f.goal_height = 0.16;
  } else {
    f.goal_width = 2.6, f.goal_depth = 0.6, f.goal_height = 1.2;
  }
  const double hx = f.length / 2, hy = f.width / 2;
  add_segment(f, "touch line -y", {-hx, -hy}, {hx, -hy});
  add_segment(f, "touch line +y", {-hx, hy}, {hx, hy});
  add_segment(f, "goal line -x", {-hx, -hy}, {-hx, hy});
  add_segment(f, "goal line +x", {hx, -hy}, {hx, hy});
  add_segment(f, "halfway line", {0, -hy}, {0, hy});
  if (ssl) {
    add_segment(f, "centre line", {-hx, 0}, {hx, 0});
    add_circle(f, "centre circle", {0, 0}, 0.5);
    add_areas(f, "defense area", 1.0, 2.0);
  } else {
    add_circle(f, "centre circle", {0, 0}, 0.75);
    add_areas(f, "goal area", 1.0, 3.0);
    add_areas(f, "penalty area", 2.0, 5.0);
    add_mark(f, "penalty mark -x", {-hx + 1.5, 0}, 0.10);
    add_mark(f, "penalty mark +x", {hx - 1.5, 0}, 0.10);
    // The halfway line already paints the centre mark's y strip.
    add_segment(f, "centre mark", {-0.05, 0}, {0.05, 0});
  }
  return f;
}

double centre_circle_radius(const FieldModel& field) {
  for (const PaintedLine& line : field.lines)
    if (line.full_circle()) return line.radius;
  return 0;
}

}  // namespace fieldlines::synth
