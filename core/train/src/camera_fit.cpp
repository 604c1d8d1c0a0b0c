#include "fieldlines/train/camera_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/matx.hpp>
#include <opencv2/core/types.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kQuarter = std::numbers::pi / 2;
// The residual of a line that misses the ground under a candidate pose: the worst there is, so
// that no pose gains by pushing a line over the horizon.
constexpr double kMissed = kQuarter / 2;

std::string fixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

// A pitch and roll offset from the start camera, radians.
struct Offset {
  double pitch = 0, roll = 0;
  double focal = 0;  // the log of the focal lengths' scale (focal_sd)
};

// The start camera with its focal lengths scaled by exp(at.focal), turned by the offsets.
GroundProjection projection(const GroundCamera& start, Offset at) {
  GroundCamera camera = start;
  camera.fx *= std::exp(at.focal), camera.fy *= std::exp(at.focal);
  return GroundProjection(camera, at.pitch, at.roll);
}

// One usable line: its image ends and how well its ground heading is known (fixed when the
// lines are chosen, so that no pose gains by making a line that does not fit look noisy).
struct Line {
  cv::Point2d p0, p1;
  double width_px = 0;
  double sd = 0;  // radians
};
using FrameSet = std::vector<std::vector<Line>>;  // per frame; empty: the frame is not used

struct GroundLine {
  cv::Point2d g0, g1;
};

// The line on the turf; none when an end misses the ground or lies farther than `max_distance`.
std::optional<GroundLine> to_ground(const GroundProjection& g, cv::Point2d p0, cv::Point2d p1, double max_distance) {
  const auto g0 = g.to_ground(p0.x, p0.y), g1 = g.to_ground(p1.x, p1.y);
  if (!g0 || !g1 || std::hypot(g0->x, g0->y) > max_distance || std::hypot(g1->x, g1->y) > max_distance)
    return std::nullopt;
  return GroundLine{*g0, *g1};
}

// An angle folded onto [-45, 45] degrees: its distance from the nearest multiple of 90.
double fold_quarter(double angle) { return angle - kQuarter * std::round(angle / kQuarter); }

// One line's residual at a pose, its sd, and the frame it belongs to.
struct Residual {
  double angle = 0;  // radians, in [-45, 45] degrees
  double sd = 0;
  std::size_t frame = 0;
};

// The robust (Geman-McClure) loss of a residual of `sd`, z^2 / (1 + z^2) with z = r / (scale sd),
// and its weight in reweighted means. Bounded: a line straying by many of its sds (a chord of the
// centre circle) adds a constant and pulls no pose towards itself.
double robust_loss(double angle, double sd, double scale) {
  const double z = angle / (scale * sd);
  return z * z / (1 + z * z);
}
double robust_weight(double angle, double sd, double scale) {
  const double z = angle / (scale * sd);
  return 1 / ((1 + z * z) * (1 + z * z) * sd * sd);
}

// The residuals of one frame's lines: each ground heading's angle to the nearest direction of
// the frame's field heading theta0. theta0 is where the frame's robust loss is least: started
// from the line heading that fits the others best (a mean would split the difference between a
// line and a stray detection, and both would pull the pose), then reweighted means of 4 theta
// on the circle.
void frame_residuals(const GroundProjection& g, std::span<const Line> lines, std::size_t frame,
                     const CameraFitParams& params, std::vector<Residual>& out) {
  const double scale = params.loss_scale_sd;
  std::vector<std::optional<double>> heading(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (const auto l = to_ground(g, lines[i].p0, lines[i].p1, params.max_distance_m))
      heading[i] = std::atan2(l->g1.y - l->g0.y, l->g1.x - l->g0.x);
  const auto frame_loss = [&](double theta0) {
    double sum = 0;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (heading[i]) sum += robust_loss(fold_quarter(*heading[i] - theta0), lines[i].sd, scale);
    return sum;
  };
  double theta0 = 0, best = std::numeric_limits<double>::infinity();
  for (const auto& h : heading)
    if (h) {
      if (const double v = frame_loss(*h); v < best) best = v, theta0 = *h;
    }
  for (int pass = 0; pass < 4; ++pass) {
    double s = 0, c = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (!heading[i]) continue;
      // Relative to theta0, so the mean stays in the mode it started from.
      const double r = fold_quarter(*heading[i] - theta0);
      const double w = robust_weight(r, lines[i].sd, scale);
      s += w * std::sin(4 * r);
      c += w * std::cos(4 * r);
    }
    theta0 += std::atan2(s, c) / 4;
  }
  for (std::size_t i = 0; i < lines.size(); ++i)
    out.push_back({heading[i] ? fold_quarter(*heading[i] - theta0) : kMissed, lines[i].sd, frame});
}

std::vector<Residual> residuals(const FrameSet& set, const GroundCamera& start, Offset at,
                                const CameraFitParams& params) {
  const GroundProjection g = projection(start, at);
  std::vector<Residual> out;
  for (std::size_t f = 0; f < set.size(); ++f) frame_residuals(g, set[f], f, params, out);
  return out;
}

// The robust loss the fit minimises: the sum of every line's.
double loss(const FrameSet& set, const GroundCamera& start, Offset at, const CameraFitParams& params) {
  double sum = 0;
  for (const Residual& r : residuals(set, start, at, params)) sum += robust_loss(r.angle, r.sd, params.loss_scale_sd);
  return sum;
}

// The focal scale's first step in Nelder-Mead (log scale: 1 %).
constexpr double kFocalStep = 0.01;

// The loss within the search (Nelder-Mead walks on where a few lines square a pose far off: on
// one rendered SSL set to a roll 40 degrees wrong), with the focal scale's prior: its log off the
// start's by focal_sd counts as a line off by its sd (the robust loss near zero is
// (r / (scale sd))^2).
double bounded_loss(const FrameSet& set, const GroundCamera& start, Offset at, const CameraFitParams& params) {
  if (std::max(std::abs(at.pitch), std::abs(at.roll)) > params.search_deg * kDeg)
    return std::numeric_limits<double>::infinity();
  const double z = params.focal_sd > 0 ? at.focal / (params.loss_scale_sd * params.focal_sd) : 0;
  return loss(set, start, at, params) + z * z;
}

// The RMS of the residuals in degrees, every line alike (what a user sees: how far the lines
// stray from square), without the `trim` share of the lines that stray most.
double trimmed_rms_deg(std::vector<Residual> rs, double trim) {
  std::ranges::sort(rs, {}, [](const Residual& r) { return std::abs(r.angle); });
  const auto keep = static_cast<std::size_t>(std::ceil((1 - trim) * static_cast<double>(rs.size())));
  double sum = 0;
  for (std::size_t i = 0; i < keep; ++i) sum += rs[i].angle * rs[i].angle;
  return keep > 0 ? std::sqrt(sum / static_cast<double>(keep)) / kDeg : 0;
}

// The sd of a line's ground heading: each image end moved by end_noise_px across the line turns
// the heading on the turf, by little for a long line near the camera, by much for a short one
// far off. min_sd_deg keeps one line from ruling.
double heading_sd(const GroundProjection& g, cv::Point2d p0, cv::Point2d p1, const GroundLine& l,
                   const CameraFitParams& params) {
  const cv::Point2d d = (p1 - p0) / cv::norm(p1 - p0), shift = cv::Point2d(-d.y, d.x) * params.end_noise_px;
  const double heading = std::atan2(l.g1.y - l.g0.y, l.g1.x - l.g0.x);
  const auto turn = [&](cv::Point2d a, cv::Point2d b) {
    const auto moved = to_ground(g, a, b, std::numeric_limits<double>::infinity());
    if (!moved) return kQuarter;  // an end so near the horizon that a pixel loses it
    return std::abs(std::remainder(std::atan2(moved->g1.y - moved->g0.y, moved->g1.x - moved->g0.x) - heading, std::numbers::pi));
  };
  const double t0 = turn(p0 + shift, p1), t1 = turn(p0, p1 + shift), floor = params.min_sd_deg * kDeg;
  return std::sqrt(t0 * t0 + t1 * t1 + floor * floor);
}

// The share of the residuals' information (1 / sd^2) in lines that fit, within loss_scale sds.
double fitting_share(std::span<const Residual> rs, double scale) {
  double all = 0, fitting = 0;
  for (const Residual& r : rs) {
    all += 1 / (r.sd * r.sd);
    if (std::abs(r.angle) <= scale * r.sd) fitting += 1 / (r.sd * r.sd);
  }
  return all > 0 ? fitting / all : 0;
}

// The sds of the fitted pitch and roll (radians) from the fitting lines' residuals: the inverse
// of the information sum J J^T / sd^2, J a residual's change with the pose (central
// differences; the frames' headings follow, as they do in the fit). Infinite when the lines do
// not pin the pose down (too few, in too few directions).
std::array<double, 2> pose_sd(const FrameSet& set, const GroundCamera& start, Offset at, std::span<const Residual> rs,
                              const CameraFitParams& params) {
  const int n = params.focal_sd > 0 ? 3 : 2;
  const std::array<double, 3> h{0.01 * kDeg, 0.01 * kDeg, 1e-4};
  std::array<std::vector<double>, 3> jacobian;  // per parameter, per residual
  for (int k = 0; k < n; ++k) {
    Offset plus = at, minus = at;
    (k == 0 ? plus.pitch : k == 1 ? plus.roll : plus.focal) += h[k];
    (k == 0 ? minus.pitch : k == 1 ? minus.roll : minus.focal) -= h[k];
    const auto rp = residuals(set, start, plus, params), rm = residuals(set, start, minus, params);
    for (std::size_t i = 0; i < rs.size(); ++i) jacobian[k].push_back((rp[i].angle - rm[i].angle) / (2 * h[k]));
  }
  cv::Matx33d info = cv::Matx33d::zeros();
  for (std::size_t i = 0; i < rs.size(); ++i) {
    if (std::abs(rs[i].angle) > params.loss_scale_sd * rs[i].sd) continue;
    const double w = 1 / (rs[i].sd * rs[i].sd);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) info(r, c) += w * jacobian[r][i] * jacobian[c][i];
  }
  // The focal scale's prior adds its own information; with the scale kept, a 1 leaves the pose's
  // 2 x 2 block as it is.
  info(2, 2) += n == 3 ? 1 / (params.focal_sd * params.focal_sd) : 1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double scale = info(0, 0) * info(1, 1) * info(2, 2);
  if (!(cv::determinant(info) > 1e-12 * scale)) return {kInf, kInf};
  const cv::Matx33d cov = info.inv(cv::DECOMP_SVD);
  return {std::sqrt(cov(0, 0)), std::sqrt(cov(1, 1))};
}

// The lines that reach the turf under `g`, per frame; a frame keeps its lines only when it has
// two or more (one line alone tells no direction apart from the frame's unknown yaw).
FrameSet usable_lines(std::span<const FrameLines> frames, const GroundProjection& g, const CameraFitParams& params) {
  FrameSet set(frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    for (const Marking& m : frames[f].markings) {
      const cv::Point2d p0(m.x0, m.y0), p1(m.x1, m.y1);
      if (!(cv::norm(p1 - p0) >= params.min_length_px)) continue;
      const auto l = to_ground(g, p0, p1, params.max_distance_m);
      if (!l) continue;
      const double sd = heading_sd(g, p0, p1, *l, params);
      if (sd <= params.max_sd_deg * kDeg) set[f].push_back({p0, p1, m.width, sd});
    }
    if (set[f].size() < 2) set[f].clear();
  }
  return set;
}

int count_lines(const FrameSet& set) {
  int n = 0;
  for (const auto& lines : set) n += static_cast<int>(lines.size());
  return n;
}

int count_frames(const FrameSet& set) {
  return static_cast<int>(std::ranges::count_if(set, [](const auto& lines) { return !lines.empty(); }));
}

// True when two of the lines' image directions differ by `min_angle` or more (modulo 180).
bool two_directions(const FrameSet& set, double min_angle) {
  std::optional<double> first;
  for (const auto& lines : set)
    for (const Line& l : lines) {
      const double a = std::atan2(l.p1.y - l.p0.y, l.p1.x - l.p0.x);
      if (!first) first = a;
      const double d = std::remainder(a - *first, std::numbers::pi);
      if (std::abs(d) >= min_angle) return true;
    }
  return false;
}

std::string frame_name(std::span<const FrameLines> frames, std::size_t f) {
  return frames[f].name.empty() ? "frame " + std::to_string(f) : frames[f].name;
}

// True when some pixel of the frame sees the turf: the image is convex and the ground a
// half-plane of it, so one of its corners does if any pixel does.
bool sees_ground(const FrameLines& frame, const GroundProjection& g) {
  if (frame.width <= 0 || frame.height <= 0) return true;  // size unknown: the lines decide
  const double w = frame.width - 1, h = frame.height - 1;
  for (const auto& [u, v] : {std::array{0.0, h}, {w, h}, {0.0, 0.0}, {w, 0.0}})
    if (g.to_ground(u, v)) return true;
  return false;
}

// Nelder-Mead on the offsets (pitch and roll, and the focal scale when `dims` is 3), from `from`
// with first steps of `step` (radians; `focal_step` for the scale), until the simplex is smaller
// than `tolerance`.
Offset nelder_mead(const auto& f, Offset from, double step, double tolerance, int dims = 2, double focal_step = 0) {
  using Point = std::array<double, 3>;
  struct Vertex {
    Point x;
    double value;
  };
  const auto offset = [](const Point& x) { return Offset{x[0], x[1], x[2]}; };
  const auto at = [&](const Point& x) { return Vertex{x, f(offset(x))}; };
  const auto mix = [](const Point& a, const Point& b, double t) {  // a + t (b - a)
    return Point{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  };
  const auto distance = [](const Point& a, const Point& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  const auto n = static_cast<std::size_t>(dims);
  std::vector<Vertex> s;
  const Point origin{from.pitch, from.roll, from.focal};
  s.push_back(at(origin));
  for (std::size_t k = 0; k < n; ++k) {
    Point x = origin;
    x[k] += k < 2 ? step : focal_step;
    s.push_back(at(x));
  }
  for (int iteration = 0; iteration < 600; ++iteration) {
    std::ranges::sort(s, {}, &Vertex::value);
    double size = 0;
    for (std::size_t k = 1; k <= n; ++k) size = std::max(size, distance(s[k].x, s[0].x));
    if (size < tolerance) break;
    Point centre{};
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t d = 0; d < 3; ++d) centre[d] += s[k].x[d] / static_cast<double>(n);
    Vertex& worst = s[n];
    const Vertex reflected = at(mix(worst.x, centre, 2));
    if (reflected.value < s[0].value) {
      const Vertex expanded = at(mix(worst.x, centre, 3));
      worst = expanded.value < reflected.value ? expanded : reflected;
    } else if (reflected.value < s[n - 1].value) {
      worst = reflected;
    } else {
      const Vertex contracted = reflected.value < worst.value ? at(mix(worst.x, centre, 1.5)) : at(mix(worst.x, centre, 0.5));
      if (contracted.value < std::min(reflected.value, worst.value)) {
        worst = contracted;
      } else {
        for (std::size_t k = 1; k <= n; ++k) s[k] = at(mix(s[0].x, s[k].x, 0.5));
      }
    }
  }
  std::ranges::sort(s, {}, &Vertex::value);
  return offset(s[0].x);
}

// The same lines with every sd at least `sd`: a loss whose valleys are as wide as the grid's
// step, so that a grid point finds the right one (a line known to a tenth of a degree sees
// every pose half a degree off as equally wrong).
FrameSet coarsened(FrameSet set, double sd) {
  for (auto& lines : set)
    for (Line& l : lines) l.sd = std::hypot(l.sd, sd);
  return set;
}

// The best offset of a grid within +-search of the start, refined by Nelder-Mead on the
// coarsened loss and then on the lines' own.
Offset fit_offset(const FrameSet& set, const GroundCamera& start, const CameraFitParams& params) {
  const double search = params.search_deg * kDeg, step = params.grid_step_deg * kDeg;
  const FrameSet coarse = coarsened(set, 2 * step);
  const auto f = [&](Offset x) { return loss(coarse, start, x, params); };
  const int n = static_cast<int>(std::floor(search / step));
  Offset best;
  double best_value = std::numeric_limits<double>::infinity();
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const Offset x{i * step, j * step};
      if (const double v = f(x); v < best_value) best_value = v, best = x;
    }
  const Offset near = nelder_mead(f, best, step / 2, 1e-3 * kDeg);
  return nelder_mead([&](Offset x) { return bounded_loss(set, start, x, params); }, near, step / 4, 1e-4 * kDeg,
                     params.focal_sd > 0 ? 3 : 2, kFocalStep);
}

// The stripes' ground width across their middles at the start height: for each fitting line
// at least `min_width_px` wide, its two edges' points across the middle in the image, put on the
// turf, and their distance across the line's ground direction.
std::vector<double> ground_widths(const FrameSet& set, const GroundProjection& g, std::span<const Residual> rs,
                                  const CameraFitParams& params) {
  std::vector<double> widths;
  std::size_t k = 0;
  for (const auto& lines : set)
    for (const Line& l : lines) {
      const Residual& r = rs[k++];
      if (!(l.width_px >= params.min_width_px) || std::abs(r.angle) > params.loss_scale_sd * r.sd) continue;
      const cv::Point2d d = (l.p1 - l.p0) / cv::norm(l.p1 - l.p0), normal(-d.y, d.x);
      const cv::Point2d middle = (l.p0 + l.p1) / 2, half = normal * (l.width_px / 2);
      const auto ends = to_ground(g, l.p0, l.p1, params.max_distance_m);
      const auto a = g.to_ground(middle.x + half.x, middle.y + half.y);
      const auto b = g.to_ground(middle.x - half.x, middle.y - half.y);
      if (!ends || !a || !b) continue;
      const cv::Point2d along = ends->g1 - ends->g0, across = *a - *b;
      const double length = cv::norm(along);
      if (length > 0) widths.push_back(std::abs(along.cross(across)) / length);
    }
  return widths;
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::ranges::nth_element(v, mid);
  if (v.size() % 2) return *mid;
  return (*mid + *std::max_element(v.begin(), mid)) / 2;
}

}  // namespace

void validate(const CameraFitParams& p) {
  const auto check = [](bool ok, const std::string& what) {
    if (!ok) throw Error("camera fit: " + what);
  };
  check(std::isfinite(p.search_deg) && p.search_deg > 0 && p.search_deg <= 45, "search_deg must be in (0, 45]");
  check(std::isfinite(p.grid_step_deg) && p.grid_step_deg >= 0.05 && p.grid_step_deg <= p.search_deg,
        "grid_step_deg must be in [0.05, search_deg]");
  check(std::isfinite(p.max_distance_m) && p.max_distance_m > 0, "max_distance_m must be positive");
  check(std::isfinite(p.end_noise_px) && p.end_noise_px > 0, "end_noise_px must be positive");
  check(std::isfinite(p.min_sd_deg) && p.min_sd_deg > 0 && p.min_sd_deg < p.max_sd_deg,
        "min_sd_deg must be positive and below max_sd_deg");
  check(std::isfinite(p.min_length_px) && p.min_length_px >= 0, "min_length_px must be >= 0");
  check(std::isfinite(p.loss_scale_sd) && p.loss_scale_sd > 0, "loss_scale_sd must be positive");
  check(std::isfinite(p.trim_fraction) && p.trim_fraction >= 0 && p.trim_fraction < 1, "trim_fraction must be in [0, 1)");
  check(std::isfinite(p.max_rms_deg) && p.max_rms_deg > 0, "max_rms_deg must be positive");
  check(p.min_frames >= 1, "min_frames must be at least 1");
  check(std::isfinite(p.max_pose_sd_deg) && p.max_pose_sd_deg > 0, "max_pose_sd_deg must be positive");
  check(std::isfinite(p.focal_sd) && p.focal_sd >= 0 && p.focal_sd <= 0.2, "focal_sd must be in [0, 0.2]");
  check(std::isfinite(p.min_fitting_share) && p.min_fitting_share >= 0 && p.min_fitting_share <= 1,
        "min_fitting_share must be in [0, 1]");
  check(std::isfinite(p.min_direction_deg) && p.min_direction_deg > 0 && p.min_direction_deg <= 90,
        "min_direction_deg must be in (0, 90]");
  check(!p.line_width_m || (std::isfinite(*p.line_width_m) && *p.line_width_m > 0 && *p.line_width_m <= 0.5),
        "the line width must be a number of metres in (0, 0.5]");
  check(std::isfinite(p.min_width_px) && p.min_width_px >= 0, "min_width_px must be >= 0");
}

CameraFit fit_camera(std::span<const FrameLines> frames, const GroundCamera& start, const CameraFitParams& params) {
  validate(params);
  validate(start);
  if (frames.empty()) throw Error("camera fit: no frames");
  const GroundProjection at_start(start);
  const std::string pose = "pitch " + fixed(start.pitch_rad / kDeg, 1) + " deg, roll " + fixed(start.roll_rad / kDeg, 1) + " deg";
  if (std::ranges::none_of(frames, [&](const FrameLines& f) { return sees_ground(f, at_start); }))
    throw Error("the start camera (" + pose +
                ") sees no ground: its horizon lies below the whole image. Is the pitch's sign right (positive looks down)?");
  std::size_t markings = 0;
  for (const FrameLines& f : frames) markings += f.markings.size();
  if (markings == 0)
    throw Error("no lines: none of the " + std::to_string(frames.size()) +
                " frames shows a painted line the detector took for a stripe (field in view? thresholds?)");

  const FrameSet start_set = usable_lines(frames, at_start, params);
  const int start_lines = count_lines(start_set);
  if (start_lines == 0 && std::ranges::all_of(frames, [&](const FrameLines& f) {
        return std::ranges::none_of(f.markings, [&](const Marking& m) {
          return to_ground(at_start, {m.x0, m.y0}, {m.x1, m.y1}, params.max_distance_m).has_value();
        });
      }))
    throw Error("all " + std::to_string(markings) + " lines lie above the start camera's horizon or farther than " +
                fixed(params.max_distance_m, 0) + " m on the ground (" + pose + ")");
  if (start_lines < 2 || !two_directions(start_set, params.min_direction_deg * kDeg))
    throw Error("too few lines: the frames hold " + std::to_string(start_lines) +
                " usable lines in frames of two or more; the fit needs at least 2 lines in 2 directions");
  if (const int n = count_frames(start_set); n < params.min_frames)
    throw Error("too few frames with lines: " + std::to_string(n) + " of " + std::to_string(frames.size()) +
                " show two usable lines or more, and the fit needs " + std::to_string(params.min_frames) +
                " (in fewer, poses far apart can square the few lines alike)");

  // The lines chosen at the start pose are fitted; those the fitted pose puts on the ground
  // (a start far off loses lines near the horizon) are fitted again from there.
  const Offset first = fit_offset(start_set, start, params);
  const FrameSet set = usable_lines(frames, projection(start, first), params);
  if (count_lines(set) < 2 || count_frames(set) < params.min_frames)
    throw Error("too few lines: the fitted pose puts fewer than " + std::to_string(params.min_frames) +
                " frames of two lines or more on the ground");
  const auto f = [&](Offset x) { return bounded_loss(set, start, x, params); };
  const Offset fitted = nelder_mead(f, first, params.grid_step_deg * kDeg / 4, 1e-4 * kDeg, params.focal_sd > 0 ? 3 : 2, kFocalStep);

  CameraFit fit;
  fit.camera = start;
  fit.camera.pitch_rad += fitted.pitch;
  fit.camera.roll_rad += fitted.roll;
  fit.focal_scale = std::exp(fitted.focal);
  fit.camera.fx *= fit.focal_scale, fit.camera.fy *= fit.focal_scale;
  fit.rms_before_deg = trimmed_rms_deg(residuals(start_set, start, {}, params), params.trim_fraction);
  const std::vector<Residual> after = residuals(set, start, fitted, params);
  fit.rms_after_deg = trimmed_rms_deg(after, params.trim_fraction);
  fit.lines_used = count_lines(set);
  fit.frame_fitting_share.assign(frames.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (set[i].empty()) continue;
    ++fit.frames_used;
    std::vector<Residual> own;
    std::ranges::copy_if(after, std::back_inserter(own), [&](const Residual& r) { return r.frame == i; });
    fit.frame_fitting_share[i] = fitting_share(own, params.loss_scale_sd);
  }
  fit.fitting_share = fitting_share(after, params.loss_scale_sd);
  // A robust fit may square the lines of some frames and give up on the others: refused when
  // the lines stray overall or too little of what they tell fits.
  if (!(fit.rms_after_deg <= params.max_rms_deg) || fit.fitting_share < params.min_fitting_share) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < frames.size(); ++i)
      if (!std::isnan(fit.frame_fitting_share[i])) order.push_back(i);
    std::ranges::sort(order, {}, [&](std::size_t i) { return fit.frame_fitting_share[i]; });
    std::string worst;
    for (std::size_t k = 0; k < std::min<std::size_t>(3, order.size()); ++k)
      worst += (k ? ", " : "") + frame_name(frames, order[k]) + " " + fixed(100 * fit.frame_fitting_share[order[k]], 0) + " %";
    throw Error("the frames contradict each other: after the fit the lines stray by " + fixed(fit.rms_after_deg, 1) +
                " deg RMS (at most " + fixed(params.max_rms_deg, 1) + ") and " + fixed(100 * fit.fitting_share, 0) +
                " % of their weight fits (at least " + fixed(100 * params.min_fitting_share, 0) + "; least: " + worst +
                "). Do all frames share one camera pitch, roll and height, and are their lines field lines?");
  }



  const auto [pitch_sd, roll_sd] = pose_sd(set, start, fitted, after, params);
  fit.pitch_sd_deg = pitch_sd / kDeg, fit.roll_sd_deg = roll_sd / kDeg;
  if (!(std::max(fit.pitch_sd_deg, fit.roll_sd_deg) <= params.max_pose_sd_deg)) {
    const auto sd = [](double v) { return v > 45 ? std::string("over 45") : fixed(v, 1); };
    throw Error("the lines do not pin the pose down: " + std::to_string(fit.lines_used) + " lines in " +
                std::to_string(fit.frames_used) + " frames leave the pitch uncertain by " + sd(fit.pitch_sd_deg) +
                " deg and the roll by " + sd(fit.roll_sd_deg) + " (at most " + fixed(params.max_pose_sd_deg, 1) +
                "); more frames, with long lines in two directions, would pin it down");
  }

  const std::vector<double> widths = ground_widths(set, projection(start, fitted), after, params);
  fit.widths_used = static_cast<int>(widths.size());
  if (!widths.empty()) fit.median_width_m = median(widths);
  if (params.line_width_m) {
    if (widths.empty())
      throw Error("the height needs the stripes' widths, and no fitting stripe " + fixed(params.min_width_px, 0) +
                  " px wide or more measured one");
    fit.camera.height_m = start.height_m * *params.line_width_m / fit.median_width_m;
    fit.height_fitted = true;
  }
  validate(fit.camera);
  return fit;
}

}  // namespace fieldlines
