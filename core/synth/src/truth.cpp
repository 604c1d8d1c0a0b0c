#include "fieldlines/synth/truth.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/json_file.hpp"

namespace fieldlines::synth {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using nlohmann::json;

constexpr double kRad = 180.0 / 3.14159265358979323846;
constexpr JsonFileFormat kFormat{"schema", "fieldlines-synth-truth", "synthetic ground truth", "ground-truth",
                                 GroundTruth::kVersion, JsonFileFormat::Newer::UpdateFieldlines};

// Douglas-Peucker on (x, y) that also keeps vertices where the width bends.
void simplify(const std::vector<TruthPoint>& in, std::size_t a, std::size_t b, double tol,
              std::vector<TruthPoint>& out) {
  const Vector2d pa(in[a].x, in[a].y), pb(in[b].x, in[b].y);
  const Vector2d ab = pb - pa;
  const double len = ab.norm();
  double worst = 0;
  std::size_t split = a;
  for (std::size_t i = a + 1; i < b; ++i) {
    const Vector2d p(in[i].x, in[i].y);
    const double t = len > 1e-9 ? std::clamp((p - pa).dot(ab) / (len * len), 0.0, 1.0) : 0.0;
    const double d = (p - (pa + t * ab)).norm();
    const double w = std::abs(in[i].width - (in[a].width + t * (in[b].width - in[a].width)));
    if (std::max(d, w) > worst) worst = std::max(d, w), split = i;
  }
  if (worst > tol) {
    simplify(in, a, split, tol, out);
    simplify(in, split, b, tol, out);
  } else {
    out.push_back(in[b]);
  }
}

std::vector<TruthPoint> simplified(const std::vector<TruthPoint>& pts, double tol) {
  std::vector<TruthPoint> out{pts.front()};
  simplify(pts, 0, pts.size() - 1, tol, out);
  return out;
}

bool in_image(const Vector2d& p, const Intrinsics& k) {
  return p.x() >= -0.5 && p.y() >= -0.5 && p.x() <= k.width - 0.5 && p.y() <= k.height - 0.5;
}

// True when the ray to `target` first meets `surface` right at the target.
bool sees(const World& w, const Camera& cam, const Vector3d& target, Surface surface) {
  const Hit hit = cast(w, cam.centre(), target - cam.centre());
  return hit.surface == surface && std::abs(hit.t - 1.0) < 1e-4;
}

// Image width of a strip crossing the image-space line at `p` (direction `t_img`).
float image_width(const Camera& cam, const Vector3d& p, const Vector2d& normal, double width,
                  const Vector2d& t_img) {
  const auto e1 = cam.project(p + Vector3d(normal.x(), normal.y(), 0) * (width / 2));
  const auto e2 = cam.project(p - Vector3d(normal.x(), normal.y(), 0) * (width / 2));
  if (!e1 || !e2) return 0;
  const Vector2d d = *e1 - *e2;
  return static_cast<float>(std::abs(t_img.x() * d.y() - t_img.y() * d.x()));
}

// Splits the samples of one line into visible runs, simplified; closed lines join across s = 0.
void emit_runs(std::vector<std::vector<TruthPoint>>& runs, bool closed, Label label, const std::string& name,
               double tol, std::vector<TruthFeature>& out) {
  if (closed && runs.size() > 1 && !runs.front().empty() && !runs.back().empty()) {
    runs.back().insert(runs.back().end(), runs.front().begin() + 1, runs.front().end());
    runs.erase(runs.begin());
  }
  for (const auto& run : runs) {
    if (run.size() < 2) continue;
    TruthFeature f;
    f.label = label;
    f.name = name;
    f.points = simplified(run, tol);
    if (f.length_px() >= 1.0) out.push_back(std::move(f));
  }
}

// Samples a ground curve (point/tangent at s) and collects its visible runs.
template <typename PointAt, typename Visible, typename Width>
std::vector<std::vector<TruthPoint>> trace(double length, double step, const Camera& cam, PointAt point_at,
                                           Visible visible, Width width_at) {
  std::vector<std::vector<TruthPoint>> runs;
  bool open = false;
  const int n = std::max(2, static_cast<int>(std::ceil(length / step)) + 1);
  for (int i = 0; i < n; ++i) {
    const double s = length * i / (n - 1);
    Vector2d tangent;
    const Vector3d p = point_at(s, tangent);
    const auto px = cam.project(p);
    const bool ok = px && in_image(*px, cam.intrinsics()) && visible(p, tangent);
    if (!ok) {
      open = false;
      continue;
    }
    const auto ahead = cam.project(p + 1e-3 * Vector3d(tangent.x(), tangent.y(), 0));
    Vector2d t_img = ahead ? Vector2d(*ahead - *px) : Vector2d(1, 0);
    t_img = t_img.norm() > 1e-12 ? Vector2d(t_img.normalized()) : Vector2d(1, 0);
    if (!open) runs.emplace_back(), open = true;
    runs.back().push_back({static_cast<float>(px->x()), static_cast<float>(px->y()), width_at(p, tangent, t_img)});
  }
  return runs;
}

}  // namespace

double TruthFeature::length_px() const {
  double len = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    len += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
  return len;
}

std::vector<TruthFeature> extract_features(const World& w, const Camera& cam, const TruthParams& params) {
  if (!(params.step > 0 && params.tolerance >= 0)) throw Error("truth: step must be > 0 and tolerance >= 0");
  std::vector<TruthFeature> out;
  for (const PaintedLine& line : w.field.lines) {
    auto runs = trace(
        line.length(), params.step, cam,
        [&](double s, Vector2d& t) {
          t = line.tangent(s);
          const Vector2d p = line.point(s);
          return Vector3d(p.x(), p.y(), 0);
        },
        [&](const Vector3d& p, const Vector2d&) { return sees(w, cam, p, Surface::Carpet); },
        [&](const Vector3d& p, const Vector2d& t, const Vector2d& t_img) {
          return image_width(cam, p, Vector2d(-t.y(), t.x()), line.width, t_img);
        });
    const bool closed = line.full_circle();
    emit_runs(runs, closed, Label::Marking, line.name, params.tolerance, out);
  }
  if (w.field.wall_height > 0) {
    // The wall's foot: carpet just inside it and the wall just above it must both be seen.
    const double hx = w.field.carpet_half_x(), hy = w.field.carpet_half_y(), e = 0.003;
    const Vector2d corners[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    const char* names[4] = {"wall -y", "wall +x", "wall +y", "wall -x"};
    for (int i = 0; i < 4; ++i) {
      const Vector2d a = corners[i], b = corners[(i + 1) % 4];
      const Vector2d dir = (b - a).normalized(), inward(-dir.y(), dir.x());
      auto runs = trace(
          (b - a).norm(), params.step, cam,
          [&](double s, Vector2d& t) {
            t = dir;
            const Vector2d p = a + dir * s;
            return Vector3d(p.x(), p.y(), 0);
          },
          [&](const Vector3d& p, const Vector2d&) {
            return sees(w, cam, p + Vector3d(inward.x(), inward.y(), 0) * e, Surface::Carpet) &&
                   sees(w, cam, p + Vector3d(0, 0, e), Surface::FieldWall);
          },
          [](const Vector3d&, const Vector2d&, const Vector2d&) { return 0.0f; });
      emit_runs(runs, false, Label::Boundary, names[i], params.tolerance, out);
    }
  }
  return out;
}

json to_json(const GroundTruth& t) {
  json features = json::array();
  for (const TruthFeature& f : t.features) {
    json pts = json::array();
    for (const TruthPoint& p : f.points) {
      // Rounded to 1/1000 px: exact enough, and keeps the files small and diffable.
      auto r = [](float v) { return std::round(static_cast<double>(v) * 1000.0) / 1000.0; };
      pts.push_back({r(p.x), r(p.y), r(p.width)});
    }
    features.push_back({{"label", std::string(to_string(f.label))}, {"name", f.name}, {"points", pts}});
  }
  json j = json_file_header(kFormat);
  j.update({{"image", t.image},
            {"mask", t.mask},
            {"scene", std::string(to_string(t.scene))},
            {"condition", std::string(to_string(t.condition))},
            {"seed", t.seed},
            {"index", t.index},
            {"line_width_m", t.line_width},
            {"camera",
             {{"width", t.intrinsics.width},
              {"height", t.intrinsics.height},
              {"fx", t.intrinsics.fx},
              {"fy", t.intrinsics.fy},
              {"cx", t.intrinsics.cx},
              {"cy", t.intrinsics.cy},
              {"position", {t.pose.position.x(), t.pose.position.y(), t.pose.position.z()}},
              {"yaw_deg", t.pose.yaw * kRad},
              {"pitch_deg", t.pose.pitch * kRad},
              {"roll_deg", t.pose.roll * kRad}}},
            {"mask_classes", {{"0", "other"}, {"1", "carpet"}, {"2", "paint"}, {"3", "field wall"}, {"4", "object"}}},
            {"features", features}});
  return j;
}

std::vector<TruthPoint> truth_points_from_json(const json& feature, const std::string& ctx) {
  const auto pts = json_field<std::vector<std::vector<double>>>(feature, "points", ctx);
  if (pts.size() < 2) throw Error(ctx + ": needs at least 2 points");
  std::vector<TruthPoint> out;
  for (const auto& p : pts) {
    if (p.size() != 3) throw Error(ctx + ": each point must be [x, y, width_px]");
    for (const double v : p)
      if (!std::isfinite(v)) throw Error(ctx + ": point with a non-finite number");
    out.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  }
  return out;
}

GroundTruth truth_from_json(const json& j, const std::string& ctx) {
  require_json_file_format(j, kFormat, ctx);
  GroundTruth t;
  t.image = json_field<std::string>(j, "image", ctx);
  t.mask = json_field<std::string>(j, "mask", ctx);
  try {
    t.scene = parse_scene(json_field<std::string>(j, "scene", ctx));
    t.condition = parse_condition(json_field<std::string>(j, "condition", ctx));
  } catch (const Error& e) {
    throw Error(ctx + ": " + e.what());
  }
  t.seed = json_field<std::uint64_t>(j, "seed", ctx);
  t.index = json_field<int>(j, "index", ctx);
  t.line_width = finite_field(json_field<double>(j, "line_width_m", ctx), "line_width_m", ctx);
  const json cam = json_field<json>(j, "camera", ctx);
  const std::string cctx = ctx + ": camera";
  t.intrinsics.width = json_field<int>(cam, "width", cctx);
  t.intrinsics.height = json_field<int>(cam, "height", cctx);
  t.intrinsics.fx = finite_field(json_field<double>(cam, "fx", cctx), "fx", cctx);
  t.intrinsics.fy = finite_field(json_field<double>(cam, "fy", cctx), "fy", cctx);
  t.intrinsics.cx = finite_field(json_field<double>(cam, "cx", cctx), "cx", cctx);
  t.intrinsics.cy = finite_field(json_field<double>(cam, "cy", cctx), "cy", cctx);
  const auto pos = json_field<std::vector<double>>(cam, "position", cctx);
  if (pos.size() != 3) throw Error(cctx + ": 'position' must have 3 numbers");
  t.pose.position = {finite_field(pos[0], "position", cctx), finite_field(pos[1], "position", cctx),
                     finite_field(pos[2], "position", cctx)};
  t.pose.yaw = finite_field(json_field<double>(cam, "yaw_deg", cctx), "yaw_deg", cctx) / kRad;
  t.pose.pitch = finite_field(json_field<double>(cam, "pitch_deg", cctx), "pitch_deg", cctx) / kRad;
  t.pose.roll = finite_field(json_field<double>(cam, "roll_deg", cctx), "roll_deg", cctx) / kRad;
  const auto features = json_field<json>(j, "features", ctx);
  if (!features.is_array()) throw Error(ctx + ": 'features' must be an array");
  for (std::size_t i = 0; i < features.size(); ++i) {
    const std::string fctx = ctx + ": features[" + std::to_string(i) + "]";
    TruthFeature f;
    const auto label = json_field<std::string>(features[i], "label", fctx);
    if (!parse_label(label, f.label) || (f.label != Label::Marking && f.label != Label::Boundary))
      throw Error(fctx + ": label must be 'marking' or 'boundary', got '" + label + "'");
    f.name = json_field<std::string>(features[i], "name", fctx);
    f.points = truth_points_from_json(features[i], fctx);
    t.features.push_back(std::move(f));
  }
  return t;
}

GroundTruth load_truth(const std::filesystem::path& path) {
  const json j = parse_json_text(read_file(path), path.string());
  return truth_from_json(j, path.string());
}

void save_truth(const std::filesystem::path& path, const GroundTruth& truth) {
  // Compact: one image has hundreds of points, and tools read it, not people.
  write_file_atomically(path, to_json(truth).dump() + "\n");
}

}  // namespace fieldlines::synth
