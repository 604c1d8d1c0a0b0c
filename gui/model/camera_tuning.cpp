#include "gui/model/camera_tuning.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "fieldlines/data/palette.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines::studio {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Image pixel indices span [-0.5, size - 0.5] (pixel centres at whole numbers, as the camera's
// principal point (size - 1) / 2 has it).
struct Box {
  double x0, y0, x1, y1;
};
Box image_box(int width, int height) { return {-0.5, -0.5, width - 0.5, height - 0.5}; }

// The part [t0, t1] of a + t (b - a) inside `box` (Liang-Barsky); t0, t1 bound the search
// (+-infinity for a whole line). False when none of it is inside.
bool clip(const Box& box, cv::Point2d a, cv::Point2d b, double& t0, double& t1) {
  const cv::Point2d d = b - a;
  const std::array<std::pair<double, double>, 4> edges{{{-d.x, a.x - box.x0}, {d.x, box.x1 - a.x},
                                                        {-d.y, a.y - box.y0}, {d.y, box.y1 - a.y}}};
  for (const auto& [p, q] : edges) {
    if (p == 0) {
      if (q < 0) return false;
      continue;
    }
    const double t = q / p;
    if (p < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  }
  return t0 <= t1;
}

// The ground segment [a, b] as the camera sees it, cut to the image: none when no part of it is
// both in front of the camera and inside the image. In front of the camera is a half-plane of
// the turf, so the visible part of the segment is one interval, found by bisection from its
// visible end.
std::optional<GridLine> visible_piece(const GroundProjection& projection, const Box& box, cv::Point2d a,
                                      cv::Point2d b) {
  std::optional<cv::Point2d> ia = projection.to_image(a), ib = projection.to_image(b);
  if (!ia && !ib) return std::nullopt;
  if (!ia || !ib) {
    cv::Point2d seen = ia ? a : b, hidden = ia ? b : a;
    for (int i = 0; i < 50; ++i) {
      const cv::Point2d mid = 0.5 * (seen + hidden);
      (projection.to_image(mid) ? seen : hidden) = mid;
    }
    (ia ? ib : ia) = projection.to_image(seen);
    if (!ia || !ib) return std::nullopt;
  }
  double t0 = 0, t1 = 1;
  if (!clip(box, *ia, *ib, t0, t1)) return std::nullopt;
  const cv::Point2d d = *ib - *ia;
  return GridLine{*ia + t0 * d, *ia + t1 * d};
}

bool whole_metre(double metres) { return std::abs(metres - std::round(metres)) < 1e-6; }

constexpr Rgba rgba(palette::Rgb c, std::uint8_t alpha = 255) { return {c.r, c.g, c.b, alpha}; }
constexpr Rgba kGridColour{200, 200, 200, 70};
constexpr Rgba kViewColour{120, 170, 255, 200};
constexpr Rgba kRobotColour{120, 170, 255, 255};

}  // namespace

// ---------------------------------------------------------------- the pose

CameraPose pose_of(const GroundCamera& camera) {
  return {camera.pitch_rad / kDeg, camera.roll_rad / kDeg, camera.height_m * 100};
}

GroundCamera with_pose(GroundCamera camera, const CameraPose& pose) {
  const auto set = [](double& to, double value, double lo, double hi, double unit) {
    if (std::isfinite(value)) to = std::clamp(value, lo, hi) * unit;
  };
  set(camera.pitch_rad, pose.pitch_deg, -kMaxAngleDeg, kMaxAngleDeg, kDeg);
  set(camera.roll_rad, pose.roll_deg, -kMaxAngleDeg, kMaxAngleDeg, kDeg);
  set(camera.height_m, pose.height_cm, kMinHeightCm, kMaxHeightCm, 0.01);
  return camera;
}

GroundCamera typical_camera(int width, int height) {
  if (width <= 0 || height <= 0) throw Error("no image to size a typical camera for");
  GroundCamera c;
  c.fx = c.fy = width;
  c.cx = (width - 1) / 2.0;
  c.cy = (height - 1) / 2.0;
  c.pitch_rad = 30 * kDeg;
  c.height_m = 0.6;
  return c;
}

std::string intrinsics_note(const GroundCamera& camera, int width, int height) {
  if (width <= 0 || height <= 0) return {};
  const Box box = image_box(width, height);
  if (camera.cx >= box.x0 && camera.cx <= box.x1 && camera.cy >= box.y0 && camera.cy <= box.y1) return {};
  char note[200];
  std::snprintf(note, sizeof note,
                "the camera's principal point (%.1f, %.1f) lies outside this %dx%d image: a camera for "
                "another image size?",
                camera.cx, camera.cy, width, height);
  return note;
}

// ---------------------------------------------------------------- the ground grid

void build_ground_grid(const GroundCamera& camera, int width, int height, const GridParams& params, GroundGrid& out) {
  out.lines.clear();
  out.horizon.reset();
  if (width <= 0 || height <= 0 || !(params.step_m > 0) || !(params.far_m > 0) || !(params.half_width_m > 0)) return;
  const GroundProjection projection(camera);
  const Box box = image_box(width, height);
  const auto add = [&](cv::Point2d a, cv::Point2d b, bool major) {
    if (auto piece = visible_piece(projection, box, a, b)) {
      piece->major = major;
      out.lines.push_back(*piece);
    }
  };
  const auto steps = [&](double extent) { return static_cast<int>(std::floor(extent / params.step_m + 1e-9)); };
  for (int k = 1; k <= steps(params.far_m); ++k) {  // across: x = k step
    const double x = k * params.step_m;
    add({x, -params.half_width_m}, {x, params.half_width_m}, whole_metre(x));
  }
  for (int k = -steps(params.half_width_m); k <= steps(params.half_width_m); ++k) {  // along: y = k step
    const double y = k * params.step_m;
    add({0, y}, {params.far_m, y}, k == 0 || whole_metre(y));
  }
  // The horizon through the vanishing points of two ground directions ahead: points a thousand
  // kilometres away lie within a thousandth of a pixel of them.
  constexpr double kFar = 1e6, kSpread = 0.5;  // radians either side of straight ahead
  const auto left = projection.to_image({kFar * std::cos(kSpread), kFar * std::sin(kSpread)});
  const auto right = projection.to_image({kFar * std::cos(kSpread), -kFar * std::sin(kSpread)});
  if (!left || !right) return;
  double t0 = -HUGE_VAL, t1 = HUGE_VAL;
  if (!clip(box, *left, *right, t0, t1) || !std::isfinite(t0) || !std::isfinite(t1)) return;
  const cv::Point2d d = *right - *left;
  out.horizon = GridLine{*left + t0 * d, *left + t1 * d, true};
}

ScreenSegment to_screen(const GridLine& line, const ViewTransform& view) {
  Segment s;
  s.x0 = static_cast<float>(line.a.x), s.y0 = static_cast<float>(line.a.y);
  s.x1 = static_cast<float>(line.b.x), s.y1 = static_cast<float>(line.b.y);
  return to_screen(s, view);
}

// ---------------------------------------------------------------- the top view

namespace {
constexpr float kMargin = 12;  // screen px between the camera's foot and the panel's bottom edge
}

TopView::TopView(const Rect& panel, double range_m) : panel_(panel.normalised()) {
  const float up = std::max(panel_.height() - kMargin, 1.0f), half = std::max(0.5f * panel_.width(), 1.0f);
  scale_ = std::min(up, half) / static_cast<float>(range_m > 0 ? range_m : 1);
  foot_ = {0.5f * (panel_.min.x + panel_.max.x), panel_.max.y - kMargin};
}

Vec2 TopView::to_panel(cv::Point2d ground) const {
  return {foot_.x - static_cast<float>(ground.y) * scale_, foot_.y - static_cast<float>(ground.x) * scale_};
}

cv::Point2d TopView::to_ground(Vec2 panel) const {
  return {static_cast<double>((foot_.y - panel.y) / scale_), static_cast<double>((foot_.x - panel.x) / scale_)};
}

namespace {

void add_metre_grid(const TopView& view, TopViewDrawing& out) {
  const Rect& p = view.panel();
  const cv::Point2d far_left = view.to_ground(p.min), near_right = view.to_ground(p.max);
  for (double x = std::ceil(near_right.x); x <= far_left.x; ++x)
    out.lines.push_back({view.to_panel({x, far_left.y}), view.to_panel({x, near_right.y}), kGridColour});
  for (double y = std::ceil(near_right.y); y <= far_left.y; ++y)
    out.lines.push_back({view.to_panel({far_left.x, y}), view.to_panel({near_right.x, y}), kGridColour});
}

// The image's left, bottom and right edges on the turf, up to where they meet the horizon (or
// run far past the panel).
void add_field_of_view(const GroundCamera& camera, int width, int height, const TopView& view, TopViewDrawing& out) {
  constexpr int kSamples = 32;
  const GroundProjection projection(camera);
  const Box box = image_box(width, height);
  const std::array<std::pair<cv::Point2d, cv::Point2d>, 3> edges{{{{box.x0, box.y0}, {box.x0, box.y1}},
                                                                  {{box.x0, box.y1}, {box.x1, box.y1}},
                                                                  {{box.x1, box.y1}, {box.x1, box.y0}}}};
  const double limit = 3 * std::max(view.panel().width(), view.panel().height()) / view.pixels_per_metre();
  for (const auto& [from, to] : edges) {
    std::optional<Vec2> last;
    for (int i = 0; i <= kSamples; ++i) {
      const cv::Point2d px = from + (to - from) * (static_cast<double>(i) / kSamples);
      const auto g = projection.to_ground(px.x, px.y);
      std::optional<Vec2> here;
      if (g && std::hypot(g->x, g->y) < limit) here = view.to_panel(*g);
      if (here && last) out.lines.push_back({*last, *here, kViewColour});
      last = here;
    }
  }
  out.circles.push_back({view.to_panel({0, 0}), 4, kRobotColour, 2});
}

}  // namespace

void build_top_view(const GroundFeatures& ground, const GroundCamera& camera, int width, int height, const TopView& view,
                    TopViewDrawing& out) {
  out.clear();
  add_metre_grid(view, out);
  if (width > 0 && height > 0) add_field_of_view(camera, width, height, view, out);
  const Rgba feature = rgba(palette::kFeature), boundary = rgba(palette::kFieldBoundary, 200);
  const auto at = [&](const GroundPoint& p) { return view.to_panel({p.x, p.y}); };
  for (std::size_t i = 1; i < ground.field_boundary.size(); ++i)
    out.lines.push_back({at(ground.field_boundary[i - 1]), at(ground.field_boundary[i]), boundary, 1.5f});
  for (const GroundMarkingSegment& s : ground.segments) out.lines.push_back({at(s.start), at(s.end), feature, 2});
  constexpr float kRing = 5, kTick = 14;  // screen px: a junction reads at every range
  for (const GroundIntersection& j : ground.intersections) {
    const Vec2 c = at(j.center);
    out.circles.push_back({c, kRing, feature, 1.5f});
    for (int k = 0; k < std::clamp(j.num_rays, 0, 4); ++k) {
      const auto& r = j.rays[static_cast<std::size_t>(k)];
      const Vec2 u{-static_cast<float>(r[1]), -static_cast<float>(r[0])};  // ground (x, y) on the panel
      out.lines.push_back({c + u * kRing, c + u * kTick, feature, 1.5f});
    }
    out.letters.push_back({{c.x + kRing + 2, c.y - kRing - 2}, to_string(j.type)[0], feature});
  }
  for (const GroundEllipse& e : ground.ellipses)
    out.circles.push_back({at(e.center), static_cast<float>(0.5 * e.diameter) * view.pixels_per_metre(), feature, 2});
}

}  // namespace fieldlines::studio
