#include "fieldlines/synth/render.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::synth {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// ---- texture ---------------------------------------------------------------------------------

inline float hash01(std::int64_t x, std::int64_t y, std::uint32_t salt) {
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^ salt;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
}

// Smooth value noise in [-1, 1] with cells of `cell` metres.
inline float value_noise(double x, double y, double cell, std::uint32_t salt) {
  const double fx = x / cell, fy = y / cell;
  const double ix = std::floor(fx), iy = std::floor(fy);
  float tx = static_cast<float>(fx - ix), ty = static_cast<float>(fy - iy);
  tx = tx * tx * (3 - 2 * tx);
  ty = ty * ty * (3 - 2 * ty);
  const auto xi = static_cast<std::int64_t>(ix), yi = static_cast<std::int64_t>(iy);
  const float a = hash01(xi, yi, salt), b = hash01(xi + 1, yi, salt);
  const float c = hash01(xi, yi + 1, salt), d = hash01(xi + 1, yi + 1, salt);
  return 2 * ((a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty) - 1;
}

// ---- painted-line lookup: a coarse grid over the carpet listing the lines near each cell ----

class LineGrid {
 public:
  static constexpr double kCell = 0.25, kMargin = 0.3;  // margin bounds the footprint we resolve

  explicit LineGrid(const FieldModel& f)
      : x0_(-f.carpet_half_x()), y0_(-f.carpet_half_y()),
        nx_(static_cast<int>(std::ceil(2 * f.carpet_half_x() / kCell))),
        ny_(static_cast<int>(std::ceil(2 * f.carpet_half_y() / kCell))) {
    offsets_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    const double reach = kCell * std::sqrt(0.5);
    for (int pass = 0; pass < 2; ++pass) {
      for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
          const Vector2d c(x0_ + (i + 0.5) * kCell, y0_ + (j + 0.5) * kCell);
          const std::size_t cell = static_cast<std::size_t>(j * nx_ + i);
          int count = 0;
          for (std::size_t l = 0; l < f.lines.size(); ++l) {
            Vector2d n;
            if (f.lines[l].distance(c, n) > reach + f.lines[l].width / 2 + kMargin) continue;
            if (pass == 1) ids_[offsets_[cell] + static_cast<std::size_t>(count)] = static_cast<int>(l);
            ++count;
          }
          if (pass == 0) offsets_[cell + 1] = static_cast<std::size_t>(count);
        }
      if (pass == 0) {
        for (std::size_t k = 1; k < offsets_.size(); ++k) offsets_[k] += offsets_[k - 1];
        ids_.assign(offsets_.back(), 0);
      }
    }
  }

  // The lines possibly covering ground point p: [begin, end) into ids().
  std::pair<const int*, const int*> near(double x, double y) const {
    const int i = static_cast<int>((x - x0_) / kCell), j = static_cast<int>((y - y0_) / kCell);
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return {nullptr, nullptr};
    const std::size_t cell = static_cast<std::size_t>(j * nx_ + i);
    return {ids_.data() + offsets_[cell], ids_.data() + offsets_[cell + 1]};
  }

 private:
  double x0_, y0_;
  int nx_, ny_;
  std::vector<std::size_t> offsets_;
  std::vector<int> ids_;
};

// ---- per-object screen rectangles, so each ray only tests the objects it can hit ----

struct ScreenRect {
  int x0, y0, x1, y1;
};

// Bounding rectangle of the object's box in the image; edges crossing the camera plane are
// clipped to a near plane first, so walls half behind the camera get a tight rectangle.
ScreenRect screen_rect(const Object& o, const Camera& cam) {
  const Intrinsics& k = cam.intrinsics();
  constexpr double kNear = 0.01;
  Vector3d corners[8];
  for (int c = 0; c < 8; ++c)
    corners[c] = cam.to_camera({(c & 1) ? o.hi.x() : o.lo.x(), (c & 2) ? o.hi.y() : o.lo.y(),
                                (c & 4) ? o.hi.z() : o.lo.z()});
  double u0 = 1e18, v0 = 1e18, u1 = -1e18, v1 = -1e18;
  auto add = [&](const Vector3d& pc) {
    const double u = k.cx + k.fx * pc.x() / pc.z(), v = k.cy + k.fy * pc.y() / pc.z();
    u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
  };
  for (int c = 0; c < 8; ++c) {
    if (corners[c].z() >= kNear) add(corners[c]);
    for (const int bit : {1, 2, 4}) {  // the box's edges from this corner
      if (c & bit) continue;
      const Vector3d& a = corners[c];
      const Vector3d& b = corners[c | bit];
      if ((a.z() < kNear) != (b.z() < kNear)) add(a + (b - a) * ((kNear - a.z()) / (b.z() - a.z())));
    }
  }
  if (u0 > u1) return {0, 0, -1, -1};  // entirely behind the camera
  auto clampi = [](double x, int lo, int hi) {
    return static_cast<int>(std::clamp(x, static_cast<double>(lo), static_cast<double>(hi)));
  };
  return {clampi(std::floor(u0) - 2, -1, k.width), clampi(std::floor(v0) - 2, -1, k.height),
          clampi(std::ceil(u1) + 2, -1, k.width), clampi(std::ceil(v1) + 2, -1, k.height)};
}

struct Sample {
  Colour rgb;
  std::uint8_t mask;
  std::int32_t id;  // surface and object: pixels with different ids are on a geometric edge
};

class Shader {
 public:
  Shader(const World& w, const Camera& cam, const Lighting& l) : w_(w), cam_(cam), l_(l), grid_(w.field) {
    light_ = l.colour * l.level;
  }

  // `scale` is the size of the sample's footprint in pixels (1, or 1/supersample).
  Sample shade(double u, double v, double scale, std::span<const int> candidates) const {
    const Vector3d dir = cam_.ray(u, v);
    const Hit hit = cast(w_, cam_.centre(), dir, candidates, false);
    Sample s;
    s.id = static_cast<std::int32_t>(hit.surface) + 8 * (hit.object + 1);
    s.mask = kMaskOther;
    const Vector3d& p = hit.point;
    switch (hit.surface) {
      case Surface::Carpet: {
        const float coverage = paint_coverage(dir, hit.t, p.head<2>(), scale);
        const float grain = 0.05f * value_noise(p.x(), p.y(), 0.004, w_.texture_seed) +
                            0.06f * value_noise(p.x(), p.y(), 0.7, w_.texture_seed + 1);
        const Colour carpet = w_.carpet * (1 + grain);
        const Colour paint = w_.paint * (1 + 0.3f * grain);
        s.rgb = (carpet + coverage * (paint - carpet)) * l_.ground_gain(p.head<2>());
        s.mask = coverage >= 0.5f ? kMaskPaint : kMaskCarpet;
        break;
      }
      case Surface::Floor: {
        const float grain = 0.08f * value_noise(p.x(), p.y(), 0.5, w_.texture_seed + 2);
        s.rgb = w_.floor * (1 + grain) * l_.ground_gain(p.head<2>());
        break;
      }
      case Surface::RoomWall: {
        // Tile grout, box-filtered over the pixel footprint like the paint, so far tiles fade
        // instead of breaking into aliased dashes.
        const double a = std::abs(hit.normal.x()) > 0.5 ? p.y() : p.x();
        const double footprint = std::max(hit.t * dir.norm() * scale / cam_.intrinsics().fx, 1e-6);
        const float grout = std::max(grout_coverage(a, footprint), grout_coverage(p.z(), footprint));
        s.rgb = w_.room_wall * (1.0f - 0.15f * grout) * vertical_light(hit.normal);
        break;
      }
      case Surface::Ceiling:
        s.rgb = w_.ceiling;
        break;
      case Surface::FieldWall:
      case Surface::Object: {
        const Object& o = w_.objects[static_cast<std::size_t>(hit.object)];
        const Colour& c = hit.normal.z() > 0.5 ? o.top : o.colour;
        s.rgb = c * vertical_light(hit.normal);
        s.mask = hit.surface == Surface::FieldWall ? kMaskFieldWall
                 : w_.field.on_carpet(o.centre().x(), o.centre().y()) || o.bait ? kMaskObject
                                                                                : kMaskOther;
        break;
      }
      case Surface::None:
        s.rgb = Colour::Zero();
        break;
    }
    s.rgb = s.rgb.cwiseProduct(light_);
    return s;
  }

 private:
  float vertical_light(const Vector3d& n) const {
    const double direct = std::max(0.0, n.dot(l_.sun));
    return l_.ambient + (1 - l_.ambient) * static_cast<float>(direct) * 1.2f;
  }

  // Share of a pixel (footprint metres wide) covered by the grout line nearest coordinate x.
  float grout_coverage(double x, double footprint) const {
    const double half = 0.015 * w_.tile_size;  // grout is 3 % of a tile
    const double f = x / w_.tile_size - std::floor(x / w_.tile_size);
    const double d = std::min(f, 1 - f) * w_.tile_size;  // distance to the nearest grout centre
    const double overlap = std::min(half, d + footprint / 2) - std::max(-half, d - footprint / 2);
    return overlap > 0 ? static_cast<float>(std::min(1.0, overlap / footprint)) : 0.0f;
  }

  // Box-filtered coverage of the pixel's ground footprint by paint (lines combine as 1-prod(1-c)).
  float paint_coverage(const Vector3d& dir, double t, const Vector2d& p, double scale) const {
    const auto [begin, end] = grid_.near(p.x(), p.y());
    if (begin == end) return 0;
    // Ground point P(u, v) = C + t(u, v) d(u, v); its derivatives give the pixel footprint.
    const Eigen::Matrix3d& r = cam_.rotation();
    const Vector3d du = r.col(0) / cam_.intrinsics().fx, dv = r.col(1) / cam_.intrinsics().fy;
    const Vector2d pu = (t * scale) * (du - dir * (du.z() / dir.z())).head<2>();
    const Vector2d pv = (t * scale) * (dv - dir * (dv.z() / dir.z())).head<2>();
    float uncovered = 1;
    for (const int* it = begin; it != end; ++it) {
      const PaintedLine& line = w_.field.lines[static_cast<std::size_t>(*it)];
      Vector2d n;
      const double dist = line.distance(p, n);
      const double fw = std::max(std::abs(n.dot(pu)) + std::abs(n.dot(pv)), 1e-6);
      const double half = line.width / 2;
      const double overlap = std::min(half, dist + fw / 2) - std::max(-half, dist - fw / 2);
      if (overlap <= 0) continue;
      uncovered *= 1 - static_cast<float>(std::min(1.0, overlap / fw));
    }
    return 1 - uncovered;
  }

  const World& w_;
  const Camera& cam_;
  const Lighting& l_;
  LineGrid grid_;
  Colour light_;
};

}  // namespace

Rendered render(const World& world, const Camera& camera, const Lighting& lighting, const RenderParams& params) {
  if (params.supersample < 1 || params.supersample > 8)
    throw Error("render: supersample must be in [1, 8], got " + std::to_string(params.supersample));
  const Intrinsics& k = camera.intrinsics();
  const int width = k.width, height = k.height;
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw Error("render: image size must be within 1..8192 pixels");
  const Shader shader(world, camera, lighting);

  std::vector<ScreenRect> rects;
  rects.reserve(world.objects.size());
  for (const Object& o : world.objects) rects.push_back(screen_rect(o, camera));

  cv::Mat rgb(height, width, CV_32FC3);
  Rendered out;
  out.mask.create(height, width, CV_8UC1);
  std::vector<std::int32_t> ids(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  std::vector<int> row_objects, candidates;
  row_objects.reserve(world.objects.size());
  candidates.reserve(world.objects.size());

  auto objects_at = [&](int x) -> std::span<const int> {
    candidates.clear();
    for (const int i : row_objects) {
      const ScreenRect& r = rects[static_cast<std::size_t>(i)];
      if (x >= r.x0 && x <= r.x1) candidates.push_back(i);
    }
    return candidates;
  };
  auto collect_row = [&](int y) {
    row_objects.clear();
    for (int i = 0; i < static_cast<int>(rects.size()); ++i)
      if (y >= rects[static_cast<std::size_t>(i)].y0 && y <= rects[static_cast<std::size_t>(i)].y1)
        row_objects.push_back(i);
  };

  // Pass 1: one ray per pixel centre.
  for (int y = 0; y < height; ++y) {
    collect_row(y);
    auto* px = rgb.ptr<cv::Vec3f>(y);
    auto* m = out.mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      const Sample s = shader.shade(x, y, 1.0, objects_at(x));
      px[x] = {s.rgb[0], s.rgb[1], s.rgb[2]};
      m[x] = s.mask;
      ids[static_cast<std::size_t>(y * width + x)] = s.id;
    }
  }

  // Pass 2: supersample pixels whose 4-neighbourhood crosses a geometric edge.
  const int n = params.supersample;
  if (n > 1) {
    std::vector<std::uint8_t> edge(ids.size(), 0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * width + x);
        if (x + 1 < width && ids[i] != ids[i + 1]) edge[i] = edge[i + 1] = 1;
        if (y + 1 < height && ids[i] != ids[i + static_cast<std::size_t>(width)])
          edge[i] = edge[i + static_cast<std::size_t>(width)] = 1;
      }
    const double step = 1.0 / n, inv = 1.0 / (n * n);
    for (int y = 0; y < height; ++y) {
      collect_row(y);
      auto* px = rgb.ptr<cv::Vec3f>(y);
      for (int x = 0; x < width; ++x) {
        if (!edge[static_cast<std::size_t>(y * width + x)]) continue;
        const std::span<const int> objs = objects_at(x);
        Colour sum = Colour::Zero();
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            sum += shader.shade(x - 0.5 + (i + 0.5) * step, y - 0.5 + (j + 0.5) * step, step, objs).rgb;
        sum *= static_cast<float>(inv);
        px[x] = {sum[0], sum[1], sum[2]};
      }
    }
  }

  cv::Mat rgb8;
  rgb.convertTo(rgb8, CV_8UC3);
  cv::cvtColor(rgb8, out.bgr, cv::COLOR_RGB2BGR);
  return out;
}

}  // namespace fieldlines::synth
