#pragma once
// The Camera tab's geometry, window-free: the robot camera's pose as a person nudges it
// (degrees, centimetres), a typical camera to start from, the ground grid the image view draws
// over the frame, and the top view (bird's-eye, metres) of the frame's features on the ground.
//
// The studio knows the camera (ground_camera.hpp) but not where the robot stands on the field,
// so both pictures are in the robot's ground frame (x ahead, y to the left, metres from the
// camera's foot): the grid shows where the camera takes the turf to be, and in the top view
// the field's lines come out parallel or square, and the circle round, only when the pitch and
// roll are right.
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/types.hpp>

#include "fieldlines/detect/ground_camera.hpp"
#include "fieldlines/detect/ground_features.hpp"
#include "gui/model/camera_nudge.hpp"
#include "gui/model/geometry.hpp"
#include "gui/model/hit_test.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/view_transform.hpp"

namespace fieldlines::studio {

// ---------------------------------------------------------------- the pose a person nudges

// The pose is kept where GroundCamera is valid: angles within +-89 degrees, 1 cm to 10 m up.
inline constexpr double kMaxAngleDeg = 89, kMinHeightCm = 1, kMaxHeightCm = 1000;

CameraPose pose_of(const GroundCamera& camera);
// `camera` with `pose`, clamped to the limits above (a non-finite value keeps the camera's).
GroundCamera with_pose(GroundCamera camera, const CameraPose& pose);

// A camera to nudge from when none is known: fx = fy = the image width (about 53 degrees
// across), the principal point at the image's centre, pitch 30 degrees, roll 0, 0.6 m up.
// Throws fieldlines::Error for an empty size.
GroundCamera typical_camera(int width, int height);

// Why `camera` may not belong to a width x height image (its principal point outside it),
// or empty.
std::string intrinsics_note(const GroundCamera& camera, int width, int height);

// ---------------------------------------------------------------- the ground grid over the frame

struct GridParams {
  double step_m = 0.5;        // a line every step_m across and along
  double far_m = 8;           // lines reach this far ahead
  double half_width_m = 4;    // and this far to either side
};

// A straight piece of a grid line in image pixels (pixel indices, as segments: hit_test.hpp
// draws them at the pixel centres). A line on the turf is a straight line in the image (a
// pinhole camera), so each is one piece.
struct GridLine {
  cv::Point2d a, b;
  bool major = false;  // on a whole metre, or the line straight ahead (y = 0)
};

struct GroundGrid {
  std::vector<GridLine> lines;  // the parts inside the image, in front of the camera
  std::optional<GridLine> horizon;  // where the image crosses the turf's horizon; none off the image
};

// The grid of `params` through `camera` on a width x height image, into `out` (cleared). Only
// what the camera sees: every line is cut to the image and to the turf in front of the camera,
// so nothing lies above the horizon.
void build_ground_grid(const GroundCamera& camera, int width, int height, const GridParams& params, GroundGrid& out);

// A grid line on screen, as the image view draws segments.
ScreenSegment to_screen(const GridLine& line, const ViewTransform& view);

// ---------------------------------------------------------------- the top view

// Metres on the turf to a panel's screen pixels: the camera's foot at the bottom centre (a
// margin up), ahead upwards, left to the left; `range_m` ahead fills the height, or half the
// width to either side when that is smaller.
class TopView {
 public:
  TopView(const Rect& panel, double range_m);
  Vec2 to_panel(cv::Point2d ground) const;
  cv::Point2d to_ground(Vec2 panel) const;
  float pixels_per_metre() const { return scale_; }
  const Rect& panel() const { return panel_; }

 private:
  Rect panel_;
  Vec2 foot_;
  float scale_ = 1;
};

struct TopViewLine {
  Vec2 a, b;
  Rgba colour;
  float thickness = 1;
};
struct TopViewCircle {
  Vec2 centre;
  float radius = 0;
  Rgba colour;
  float thickness = 1;
};
struct TopViewLetter {
  Vec2 at;  // bottom-left
  char letter = 0;
  Rgba colour;
};
struct TopViewDrawing {
  std::vector<TopViewLine> lines;  // drawn first
  std::vector<TopViewCircle> circles;
  std::vector<TopViewLetter> letters;
  void clear() { lines.clear(), circles.clear(), letters.clear(); }
};

// What the top view draws, into `out` (cleared; capacity kept, as the tab draws it every frame):
// a faint one-metre grid, the camera's field of view on the turf (the image's edges through
// `camera`), and `ground`: the stripes' centre lines, the junctions (a ring, a tick along each
// arm, the type letter), the centre circle and the field boundary, in the image view's colours.
void build_top_view(const GroundFeatures& ground, const GroundCamera& camera, int width, int height, const TopView& view,
                    TopViewDrawing& out);

// What the Camera tab draws each frame, kept between frames so drawing allocates nothing once
// warm: the frame's features on the ground, the top view's primitives, the grid's lines.
struct CameraViewBuffers {
  GroundFeatures ground;
  TopViewDrawing top_view;
  GroundGrid grid;
};

}  // namespace fieldlines::studio
