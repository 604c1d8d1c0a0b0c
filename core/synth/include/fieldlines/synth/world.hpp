#pragma once
// Everything a camera ray can hit: the carpet with its painted lines, the SSL boundary wall,
// goals, robots, the ball, and the room around the field (floor, walls, ceiling, people,
// furniture, doors and windows). Ray casting here is shared by the renderer and the ground
// truth, so "visible" means the same thing for both.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "fieldlines/synth/field.hpp"
#include "fieldlines/train/random.hpp"

namespace fieldlines::synth {

using Colour = Eigen::Vector3f;  // R, G, B in 0..255 under neutral light

enum class Surface : std::uint8_t { None, Carpet, Floor, RoomWall, Ceiling, FieldWall, Object };

struct Object {
  enum class Shape : std::uint8_t { Box, Cylinder, Sphere };
  Shape shape = Shape::Box;
  Eigen::Vector3d lo{0, 0, 0}, hi{0, 0, 0};  // box corners; bounding box of the others
  Colour colour{128, 128, 128};
  Colour top{128, 128, 128};  // cylinders: the lid (SSL robots carry coloured markers)
  Surface surface = Surface::Object;  // FieldWall for the SSL boundary wall
  bool bait = false;                  // white edges that are not field lines

  static Object box(Eigen::Vector3d lo, Eigen::Vector3d hi, Colour colour);
  static Object cylinder(Eigen::Vector2d centre, double radius, double z0, double z1, Colour colour);
  static Object sphere(Eigen::Vector3d centre, double radius, Colour colour);
  Eigen::Vector3d centre() const { return (lo + hi) / 2; }
};

struct ClutterParams {
  int robots_min = 1, robots_max = 6;  // on the field
  double white_robot_chance = 0.25;    // each robot is white (line-like edges) with this chance
  bool ball = true;
  int people_min = 0, people_max = 5;  // standing behind the field
  int furniture_min = 1, furniture_max = 4;
  int doors_windows_min = 1, doors_windows_max = 4;  // white bait on the room walls
};
void validate(const ClutterParams& params);

struct World {
  FieldModel field;
  Eigen::Vector3d room_lo{-8, -7, 0}, room_hi{8, 7, 3.5};
  Colour carpet{92, 168, 130}, paint{236, 238, 234}, floor{150, 146, 138};
  Colour room_wall{222, 224, 222}, ceiling{200, 200, 200};
  double tile_size = 0.3;  // grout lines on the room walls
  std::uint32_t texture_seed = 0;  // carpet and floor texture
  std::vector<Object> objects;
};

struct Hit {
  double t = 0;  // ray parameter: point = origin + t * dir
  Surface surface = Surface::None;
  int object = -1;  // index in World::objects for FieldWall/Object hits
  Eigen::Vector3d point{0, 0, 0};
  Eigen::Vector3d normal{0, 0, 1};
};

// Builds a world: the field (with its SSL wall and goals) plus random clutter.
World make_world(const FieldModel& field, const ClutterParams& clutter, Rand& rand);

// The nearest hit along origin + t*dir (t > 0). The room's inside always stops the ray.
// `candidates` restricts the objects tested (the renderer's screen-space culling); all when empty
// and `all_objects` is true.
Hit cast(const World& world, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
         std::span<const int> candidates, bool all_objects);
inline Hit cast(const World& world, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) {
  return cast(world, origin, dir, {}, true);
}

// Ray / object intersection: the entry t in (t_min, t_max), with the outward normal.
bool intersect(const Object& object, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
               double t_min, double& t_max, Eigen::Vector3d& normal);

}  // namespace fieldlines::synth
