#include "fieldlines/synth/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::synth {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

Colour jitter(const Colour& c, Rand& rand, float amount) {
  const float gain = static_cast<float>(rand.uniform(1 - amount, 1 + amount));
  Colour out;
  for (int i = 0; i < 3; ++i)
    out[i] = std::clamp(c[i] * gain + static_cast<float>(rand.normal(0, amount * 40)), 0.f, 255.f);
  return out;
}

Colour random_clothing(Rand& rand) {
  static constexpr float kPalette[][3] = {{30, 60, 160}, {20, 20, 30},  {170, 30, 30},
                                          {60, 60, 65},  {200, 200, 60}, {40, 110, 60},
                                          {230, 230, 230}, {120, 70, 40}};
  const auto& p = kPalette[rand.integer(0, 7)];
  return jitter(Colour(p[0], p[1], p[2]), rand, 0.15f);
}

// A point on the room floor outside the carpet (and its wall), for people and furniture.
Vector2d spot_behind_field(const World& w, Rand& rand, double margin) {
  const double cx = w.field.carpet_half_x() + w.field.wall_thickness + margin;
  const double cy = w.field.carpet_half_y() + w.field.wall_thickness + margin;
  for (int i = 0; i < 100; ++i) {
    const Vector2d p(rand.uniform(w.room_lo.x() + margin, w.room_hi.x() - margin),
                     rand.uniform(w.room_lo.y() + margin, w.room_hi.y() - margin));
    if (std::abs(p.x()) > cx || std::abs(p.y()) > cy) return p;
  }
  return {w.room_hi.x() - margin, w.room_hi.y() - margin};
}

void add_person(World& w, Rand& rand) {
  const Vector2d p = spot_behind_field(w, rand, 0.4);
  const double h = rand.uniform(1.55, 1.9);
  const Colour trousers = random_clothing(rand), shirt = random_clothing(rand);
  const Colour skin = jitter(Colour(200, 150, 120), rand, 0.2f);
  const double legs = 0.47 * h;
  for (const double side : {-0.1, 0.1})
    w.objects.push_back(Object::box({p.x() + side - 0.07, p.y() - 0.07, 0},
                                    {p.x() + side + 0.07, p.y() + 0.07, legs}, trousers));
  w.objects.push_back(Object::box({p.x() - 0.22, p.y() - 0.13, legs},
                                  {p.x() + 0.22, p.y() + 0.13, 0.86 * h}, shirt));
  w.objects.push_back(Object::sphere({p.x(), p.y(), 0.93 * h}, 0.1, skin));
}

void add_furniture(World& w, Rand& rand) {
  const Vector2d p = spot_behind_field(w, rand, 0.9);
  const int kind = rand.integer(0, 2);
  if (kind == 0) {  // table: top and four legs
    const double hx = rand.uniform(0.5, 0.9), hy = rand.uniform(0.3, 0.45), z = 0.75;
    const Colour top = jitter(rand.chance(0.5) ? Colour(150, 110, 70) : Colour(60, 60, 60), rand, 0.15f);
    const Colour leg(40, 40, 40);
    w.objects.push_back(Object::box({p.x() - hx, p.y() - hy, z - 0.04}, {p.x() + hx, p.y() + hy, z}, top));
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0}) {
        const Vector2d c(p.x() + sx * (hx - 0.05), p.y() + sy * (hy - 0.05));
        w.objects.push_back(Object::box({c.x() - 0.02, c.y() - 0.02, 0}, {c.x() + 0.02, c.y() + 0.02, z - 0.04}, leg));
      }
  } else if (kind == 1) {  // chair
    const Colour c = jitter(rand.chance(0.5) ? Colour(180, 30, 35) : Colour(35, 35, 40), rand, 0.1f);
    w.objects.push_back(Object::box({p.x() - 0.23, p.y() - 0.23, 0.42}, {p.x() + 0.23, p.y() + 0.23, 0.5}, c));
    w.objects.push_back(Object::box({p.x() - 0.23, p.y() + 0.18, 0.5}, {p.x() + 0.23, p.y() + 0.23, 0.95}, c));
    w.objects.push_back(Object::cylinder(p, 0.03, 0, 0.42, Colour(50, 50, 50)));
  } else {  // cabinet or shelf
    const double hx = rand.uniform(0.3, 0.8), hy = rand.uniform(0.2, 0.3), h = rand.uniform(0.8, 2.0);
    w.objects.push_back(Object::box({p.x() - hx, p.y() - hy, 0}, {p.x() + hx, p.y() + hy, h},
                                    jitter(Colour(120, 115, 110), rand, 0.3f)));
  }
}

// A white door or a bright window flush with one of the room walls: straight white edges.
void add_door_or_window(World& w, Rand& rand) {
  const bool door = rand.chance(0.5);
  const double wide = door ? 0.9 : rand.uniform(0.8, 1.6);
  const double z0 = door ? 0.0 : rand.uniform(0.6, 1.1), z1 = door ? 2.0 : z0 + rand.uniform(0.6, 1.2);
  const Colour c = door ? jitter(Colour(238, 238, 232), rand, 0.04f) : Colour(250, 252, 255);
  const int side = rand.integer(0, 3);
  const double d = 0.03;
  Object o;
  if (side < 2) {  // walls at x = lo / hi
    const double x = side == 0 ? w.room_lo.x() : w.room_hi.x();
    const double y = rand.uniform(w.room_lo.y() + wide, w.room_hi.y() - wide);
    o = Object::box({x - d, y - wide / 2, z0}, {x + d, y + wide / 2, z1}, c);
  } else {
    const double y = side == 2 ? w.room_lo.y() : w.room_hi.y();
    const double x = rand.uniform(w.room_lo.x() + wide, w.room_hi.x() - wide);
    o = Object::box({x - wide / 2, y - d, z0}, {x + wide / 2, y + d, z1}, c);
  }
  o.bait = true;
  w.objects.push_back(o);
}

void add_ssl_wall_and_goals(World& w, Rand& rand) {
  const FieldModel& f = w.field;
  const double hx = f.carpet_half_x(), hy = f.carpet_half_y(), th = f.wall_thickness, h = f.wall_height;
  const Colour black = jitter(Colour(24, 24, 26), rand, 0.2f);
  auto wall = [&](Vector3d lo, Vector3d hi) {
    Object o = Object::box(lo, hi, black);
    o.surface = Surface::FieldWall;
    w.objects.push_back(o);
  };
  wall({hx, -hy - th, 0}, {hx + th, hy + th, h});
  wall({-hx - th, -hy - th, 0}, {-hx, hy + th, h});
  wall({-hx, hy, 0}, {hx, hy + th, h});
  wall({-hx, -hy - th, 0}, {hx, -hy, h});
  // Goals: three thin walls behind each goal line, standing on the carpet's run-off.
  const Colour goal = jitter(Colour(45, 45, 48), rand, 0.2f);
  const double gw = f.goal_width / 2, gd = f.goal_depth, gh = f.goal_height, t = 0.02;
  for (const double s : {-1.0, 1.0}) {
    const double x0 = s * f.length / 2 + s * f.line_width / 2, x1 = x0 + s * gd;
    w.objects.push_back(Object::box({std::min(x1, x1 + s * t), -gw - t, 0}, {std::max(x1, x1 + s * t), gw + t, gh}, goal));
    for (const double y : {-gw - t, gw})
      w.objects.push_back(Object::box({std::min(x0, x1), y, 0}, {std::max(x0, x1), y + t, gh}, goal));
  }
}

void add_kid_goals(World& w) {
  const FieldModel& f = w.field;
  const double gw = f.goal_width / 2, r = 0.05, h = f.goal_height;
  for (const double s : {-1.0, 1.0}) {
    const double x = s * (f.length / 2 + r);
    for (const double y : {-gw - r, gw + r}) {
      Object post = Object::cylinder({x, y}, r, 0, h, Colour(240, 240, 238));
      post.bait = true;
      w.objects.push_back(post);
    }
    Object bar = Object::box({x - r, -gw - r, h - 2 * r}, {x + r, gw + r, h}, Colour(240, 240, 238));
    bar.bait = true;
    w.objects.push_back(bar);
    // The net's back frame, dark so the posts stand out as they do on real fields.
    w.objects.push_back(Object::box({std::min(x, x + s * f.goal_depth), -gw, 0},
                                    {std::max(x, x + s * f.goal_depth), -gw + 0.02, h}, Colour(90, 90, 90)));
    w.objects.push_back(Object::box({std::min(x, x + s * f.goal_depth), gw - 0.02, 0},
                                    {std::max(x, x + s * f.goal_depth), gw, h}, Colour(90, 90, 90)));
  }
}

Vector2d spot_on_field(const FieldModel& f, Rand& rand) {
  return {rand.uniform(-f.length / 2, f.length / 2), rand.uniform(-f.width / 2, f.width / 2)};
}

void add_robot(World& w, Rand& rand, const ClutterParams& clutter) {
  const Vector2d p = spot_on_field(w.field, rand);
  const bool white = rand.chance(clutter.white_robot_chance);
  const Colour body = white ? Colour(235, 235, 232) : jitter(Colour(30, 30, 32), rand, 0.3f);
  if (w.field.scene == Scene::Ssl) {
    Object o = Object::cylinder(p, 0.09, 0, 0.15, body);
    o.top = rand.chance(0.5) ? Colour(40, 80, 200) : Colour(230, 210, 40);
    o.bait = white;
    w.objects.push_back(o);
    return;
  }
  const double h = rand.uniform(0.45, 0.9);
  for (const double side : {-0.06, 0.06}) {
    Object leg = Object::box({p.x() - 0.04, p.y() + side - 0.035, 0}, {p.x() + 0.04, p.y() + side + 0.035, 0.45 * h}, body);
    leg.bait = white;
    w.objects.push_back(leg);
  }
  Object torso = Object::box({p.x() - 0.07, p.y() - 0.12, 0.45 * h}, {p.x() + 0.07, p.y() + 0.12, 0.85 * h}, body);
  torso.bait = white;
  w.objects.push_back(torso);
  w.objects.push_back(Object::sphere({p.x(), p.y(), 0.85 * h + 0.07}, 0.07, jitter(Colour(60, 60, 60), rand, 0.3f)));
}

bool slab(double o, double d, double lo, double hi, double& t0, double& t1, int axis, int& enter_axis,
          double& enter_sign) {
  if (std::abs(d) < 1e-15) return o >= lo && o <= hi;
  double a = (lo - o) / d, b = (hi - o) / d;
  double sign = -1;
  if (a > b) std::swap(a, b), sign = 1;
  if (a > t0) t0 = a, enter_axis = axis, enter_sign = sign;
  t1 = std::min(t1, b);
  return t0 <= t1;
}

}  // namespace

Object Object::box(Vector3d lo, Vector3d hi, Colour colour) {
  Object o;
  o.shape = Shape::Box;
  o.lo = lo.cwiseMin(hi);
  o.hi = lo.cwiseMax(hi);
  o.colour = o.top = colour;
  return o;
}

Object Object::cylinder(Vector2d c, double radius, double z0, double z1, Colour colour) {
  Object o;
  o.shape = Shape::Cylinder;
  o.lo = {c.x() - radius, c.y() - radius, z0};
  o.hi = {c.x() + radius, c.y() + radius, z1};
  o.colour = o.top = colour;
  return o;
}

Object Object::sphere(Vector3d c, double radius, Colour colour) {
  Object o;
  o.shape = Shape::Sphere;
  o.lo = c.array() - radius;
  o.hi = c.array() + radius;
  o.colour = o.top = colour;
  return o;
}

void validate(const ClutterParams& p) {
  auto range = [](int lo, int hi, const char* what) {
    if (lo < 0 || lo > hi || hi > 100)
      throw Error(std::string("clutter: ") + what + " must satisfy 0 <= min <= max <= 100");
  };
  range(p.robots_min, p.robots_max, "robots");
  range(p.people_min, p.people_max, "people");
  range(p.furniture_min, p.furniture_max, "furniture");
  range(p.doors_windows_min, p.doors_windows_max, "doors and windows");
  if (!(p.white_robot_chance >= 0 && p.white_robot_chance <= 1))
    throw Error("clutter: white robot chance must be in [0, 1]");
}

World make_world(const FieldModel& field, const ClutterParams& clutter, Rand& rand) {
  validate(clutter);
  World w;
  w.field = field;
  const double mx = rand.uniform(1.5, 3.5), my = rand.uniform(1.5, 3.5);
  w.room_lo = {-field.carpet_half_x() - mx, -field.carpet_half_y() - my, 0};
  w.room_hi = {field.carpet_half_x() + rand.uniform(1.5, 3.5), field.carpet_half_y() + rand.uniform(1.5, 3.5),
               rand.uniform(3.0, 4.5)};
  // SSL: the mean carpet colour of the authors' real frames (about 89, 157, 121 after vignetting).
  w.carpet = jitter(field.scene == Scene::Ssl ? Colour(92, 168, 130) : Colour(60, 140, 70), rand, 0.08f);
  w.paint = jitter(Colour(236, 238, 234), rand, 0.03f);
  w.floor = jitter(Colour(150, 146, 138), rand, 0.25f);
  w.room_wall = jitter(Colour(222, 224, 222), rand, 0.08f);
  w.ceiling = jitter(Colour(205, 205, 205), rand, 0.1f);
  w.tile_size = rand.uniform(0.2, 0.5);
  w.texture_seed = static_cast<std::uint32_t>(rand.bits());
  if (field.scene == Scene::Ssl)
    add_ssl_wall_and_goals(w, rand);
  else
    add_kid_goals(w);
  const int robots = rand.integer(clutter.robots_min, clutter.robots_max);
  for (int i = 0; i < robots; ++i) add_robot(w, rand, clutter);
  if (clutter.ball) {
    const Vector2d p = spot_on_field(field, rand);
    const double r = field.scene == Scene::Ssl ? 0.0215 : 0.07;
    const Colour c = field.scene == Scene::Ssl ? Colour(250, 90, 20) : Colour(235, 235, 235);
    w.objects.push_back(Object::sphere({p.x(), p.y(), r}, r, c));
  }
  const int people = rand.integer(clutter.people_min, clutter.people_max);
  for (int i = 0; i < people; ++i) add_person(w, rand);
  const int furniture = rand.integer(clutter.furniture_min, clutter.furniture_max);
  for (int i = 0; i < furniture; ++i) add_furniture(w, rand);
  const int bait = rand.integer(clutter.doors_windows_min, clutter.doors_windows_max);
  for (int i = 0; i < bait; ++i) add_door_or_window(w, rand);
  return w;
}

bool intersect(const Object& o, const Vector3d& org, const Vector3d& dir, double t_min, double& t_max,
               Vector3d& normal) {
  switch (o.shape) {
    case Object::Shape::Box: {
      double t0 = t_min, t1 = t_max, sign = -1;
      int axis = -1;
      for (int i = 0; i < 3; ++i)
        if (!slab(org[i], dir[i], o.lo[i], o.hi[i], t0, t1, i, axis, sign)) return false;
      if (axis < 0 || t0 <= t_min || t0 >= t_max) return false;  // starts inside or out of range
      t_max = t0;
      normal = Vector3d::Zero();
      normal[axis] = sign;
      return true;
    }
    case Object::Shape::Cylinder: {
      const Vector2d c = (o.lo.head<2>() + o.hi.head<2>()) / 2;
      const double r = (o.hi.x() - o.lo.x()) / 2;
      const Vector2d oc = org.head<2>() - c;
      const double a = dir.head<2>().squaredNorm();
      double best = t_max;
      bool found = false;
      if (a > 1e-18) {  // side wall
        const double b = oc.dot(dir.head<2>()), cc = oc.squaredNorm() - r * r;
        const double disc = b * b - a * cc;
        if (disc >= 0) {
          const double t = (-b - std::sqrt(disc)) / a;
          const double z = org.z() + t * dir.z();
          if (t > t_min && t < best && z >= o.lo.z() && z <= o.hi.z()) {
            best = t, found = true;
            const Vector2d n = (oc + t * dir.head<2>()) / r;
            normal = {n.x(), n.y(), 0};
          }
        }
      }
      if (std::abs(dir.z()) > 1e-15) {  // lid or bottom
        const double zc = dir.z() < 0 ? o.hi.z() : o.lo.z();
        const double t = (zc - org.z()) / dir.z();
        if (t > t_min && t < best && (oc + t * dir.head<2>()).squaredNorm() <= r * r) {
          best = t, found = true;
          normal = {0, 0, dir.z() < 0 ? 1.0 : -1.0};
        }
      }
      if (found) t_max = best;
      return found;
    }
    case Object::Shape::Sphere: {
      const Vector3d c = o.centre();
      const double r = (o.hi.x() - o.lo.x()) / 2;
      const Vector3d oc = org - c;
      const double a = dir.squaredNorm(), b = oc.dot(dir), cc = oc.squaredNorm() - r * r;
      const double disc = b * b - a * cc;
      if (disc < 0) return false;
      const double t = (-b - std::sqrt(disc)) / a;
      if (t <= t_min || t >= t_max) return false;
      t_max = t;
      normal = (oc + t * dir) / r;
      return true;
    }
  }
  return false;
}

Hit cast(const World& w, const Vector3d& org, const Vector3d& dir, std::span<const int> candidates,
         bool all_objects) {
  Hit hit;
  // Leaving the room box (the camera is inside it): walls or ceiling.
  double t_exit = std::numeric_limits<double>::infinity();
  int exit_axis = 2;
  double exit_sign = 1;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(dir[i]) < 1e-15) continue;
    const double bound = dir[i] > 0 ? w.room_hi[i] : w.room_lo[i];
    const double t = (bound - org[i]) / dir[i];
    if (t < t_exit) t_exit = t, exit_axis = i, exit_sign = dir[i] > 0 ? -1 : 1;
  }
  hit.t = t_exit;
  hit.surface = exit_axis == 2 ? (dir.z() > 0 ? Surface::Ceiling : Surface::Floor) : Surface::RoomWall;
  hit.normal = Vector3d::Zero();
  hit.normal[exit_axis] = exit_sign;
  if (dir.z() < 0) {
    const double t = -org.z() / dir.z();
    if (t > 0 && t <= hit.t) {
      hit.t = t;
      const Vector3d p = org + t * dir;
      hit.surface = w.field.on_carpet(p.x(), p.y()) ? Surface::Carpet : Surface::Floor;
      hit.normal = {0, 0, 1};
    }
  }
  double t_max = hit.t;
  Vector3d normal;
  auto test = [&](int i) {
    if (intersect(w.objects[static_cast<std::size_t>(i)], org, dir, 1e-9, t_max, normal)) {
      hit.t = t_max;
      hit.object = i;
      hit.surface = w.objects[static_cast<std::size_t>(i)].surface;
      hit.normal = normal;
    }
  };
  if (all_objects && candidates.empty()) {
    for (int i = 0; i < static_cast<int>(w.objects.size()); ++i) test(i);
  } else {
    for (const int i : candidates) test(i);
  }
  hit.point = org + hit.t * dir;
  return hit;
}

}  // namespace fieldlines::synth
