#include "fieldlines/synth/conditions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines::synth {
namespace {

constexpr std::array<Condition, 5> kAll{Condition::Artificial, Condition::Natural, Condition::Mixed,
                                        Condition::Dim, Condition::Shadows};

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

LightPatch make_patch(const Eigen::Vector2d& origin, const Eigen::Vector2d& along, const Eigen::Vector2d& across,
                      float gain) {
  LightPatch p;
  p.corners[0] = origin;
  p.corners[1] = origin + along;
  p.corners[2] = origin + along + across;
  p.corners[3] = origin + across;
  if (cross(along, across) < 0) std::swap(p.corners[1], p.corners[3]);
  p.lo = p.hi = origin;
  for (const auto& c : p.corners) p.lo = p.lo.cwiseMin(c), p.hi = p.hi.cwiseMax(c);
  p.gain = gain;
  return p;
}

// Sunlight through a window: a bright parallelogram slanting across the field.
void add_sun_patches(Lighting& l, const World& w, Rand& rand, int count, float gain) {
  const double dir = rand.uniform(0, 6.283185307179586);
  const Eigen::Vector2d along(std::cos(dir), std::sin(dir));
  const Eigen::Vector2d skew(std::cos(dir + 1.2), std::sin(dir + 1.2));
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d o(rand.uniform(-w.field.length / 2, w.field.length / 2),
                            rand.uniform(-w.field.width / 2, w.field.width / 2));
    l.patches.push_back(make_patch(o, along * rand.uniform(0.8, 2.5), skew * rand.uniform(0.5, 1.5), gain));
  }
}

// Hard shadows: each object standing on the carpet throws a dark band away from the sun.
void add_object_shadows(Lighting& l, const World& w, float gain) {
  const Eigen::Vector2d away = -l.sun.head<2>().normalized();
  const double slope = std::sqrt(1 - l.sun.z() * l.sun.z()) / std::max(l.sun.z(), 0.2);
  for (const Object& o : w.objects) {
    if (o.surface != Surface::Object || o.lo.z() > 0.05) continue;
    if (!w.field.on_carpet(o.centre().x(), o.centre().y())) continue;
    const double radius = std::max(o.hi.x() - o.lo.x(), o.hi.y() - o.lo.y()) / 2;
    const Eigen::Vector2d side(-away.y(), away.x());
    const Eigen::Vector2d base = o.centre().head<2>() - side * radius;
    l.patches.push_back(make_patch(base, away * (o.hi.z() * slope + radius), side * 2 * radius, gain));
  }
}

}  // namespace

std::string_view to_string(Condition c) {
  switch (c) {
    case Condition::Artificial: return "artificial";
    case Condition::Natural: return "natural";
    case Condition::Mixed: return "mixed";
    case Condition::Dim: return "dim";
    case Condition::Shadows: return "shadows";
  }
  return "artificial";
}

Condition parse_condition(std::string_view text) {
  for (const Condition c : kAll)
    if (to_string(c) == text) return c;
  throw Error("unknown condition '" + std::string(text) +
              "' (expected artificial, natural, mixed, dim or shadows)");
}

std::span<const Condition> all_conditions() { return kAll; }

bool LightPatch::contains(const Eigen::Vector2d& p) const {
  if (p.x() < lo.x() || p.y() < lo.y() || p.x() > hi.x() || p.y() > hi.y()) return false;
  for (int i = 0; i < 4; ++i)
    if (cross(corners[(i + 1) % 4] - corners[i], p - corners[i]) < 0) return false;
  return true;
}

float Lighting::ground_gain(const Eigen::Vector2d& p) const {
  float g = 1.0f + static_cast<float>(gradient.dot(p));
  for (const LightPatch& patch : patches)
    if (patch.contains(p)) g *= patch.gain;
  return std::max(g, 0.05f);
}

Lighting sample_lighting(Condition condition, const World& world, Rand& rand) {
  Lighting l;
  l.condition = condition;
  const double az = rand.uniform(0, 6.283185307179586), el = rand.uniform(0.5, 1.2);
  l.sun = {std::cos(az) * std::cos(el), std::sin(az) * std::cos(el), std::sin(el)};
  const double gdir = rand.uniform(0, 6.283185307179586);
  const Eigen::Vector2d gunit(std::cos(gdir), std::sin(gdir));
  // A small random tint on top of every light: white balance is never perfect.
  Colour tint(static_cast<float>(rand.uniform(0.95, 1.05)), 1.0f, static_cast<float>(rand.uniform(0.95, 1.05)));
  switch (condition) {
    case Condition::Artificial:
      l.level = static_cast<float>(rand.uniform(0.95, 1.08));
      l.gradient = gunit * rand.uniform(0.0, 0.015);
      l.noise_sigma = static_cast<float>(rand.uniform(1.0, 2.5));
      break;
    case Condition::Natural: {
      l.level = static_cast<float>(rand.uniform(0.75, 0.95));
      l.gradient = gunit * rand.uniform(0.03, 0.07);
      const bool cool = rand.chance(0.5);
      tint = tint.cwiseProduct(cool ? Colour(0.92f, 1.0f, 1.1f) : Colour(1.08f, 1.0f, 0.88f));
      l.ambient = 0.6f;
      l.noise_sigma = static_cast<float>(rand.uniform(2.0, 3.5));
      break;
    }
    case Condition::Mixed:
      l.level = static_cast<float>(rand.uniform(0.85, 1.0));
      l.gradient = gunit * rand.uniform(0.02, 0.05);
      tint = tint.cwiseProduct(Colour(1.04f, 1.0f, 0.95f));
      add_sun_patches(l, world, rand, rand.integer(0, 2), static_cast<float>(rand.uniform(1.1, 1.25)));
      l.noise_sigma = static_cast<float>(rand.uniform(1.5, 3.0));
      break;
    case Condition::Dim:
      l.level = static_cast<float>(rand.uniform(0.4, 0.55));
      l.gradient = gunit * rand.uniform(0.0, 0.03);
      tint = tint.cwiseProduct(Colour(1.06f, 1.0f, 0.9f));
      l.noise_sigma = static_cast<float>(rand.uniform(3.5, 6.0));
      l.vignetting = 0.35f;
      break;
    case Condition::Shadows:
      l.level = static_cast<float>(rand.uniform(0.8, 0.95));
      l.gradient = gunit * rand.uniform(0.0, 0.03);
      l.ambient = 0.45f;
      add_object_shadows(l, world, static_cast<float>(rand.uniform(0.45, 0.6)));
      add_sun_patches(l, world, rand, rand.integer(1, 3), static_cast<float>(rand.uniform(1.3, 1.6)));
      l.noise_sigma = static_cast<float>(rand.uniform(1.5, 3.0));
      break;
  }
  l.colour = tint;
  l.vignetting *= static_cast<float>(rand.uniform(0.5, 1.5));
  l.blur_sigma = static_cast<float>(rand.uniform(0.4, 1.1));
  l.jpeg_quality = rand.integer(70, 95);
  return l;
}

void apply_camera_effects(cv::Mat& bgr, const Lighting& l, std::uint64_t seed) {
  CV_Assert(bgr.type() == CV_8UC3);
  if (l.vignetting > 0) {
    // Radial falloff 1 - v * r^2 (r = 1 in the corners), one gain per pixel.
    const double cx = (bgr.cols - 1) / 2.0, cy = (bgr.rows - 1) / 2.0;
    const double inv = 1.0 / (cx * cx + cy * cy);
    for (int y = 0; y < bgr.rows; ++y) {
      auto* row = bgr.ptr<cv::Vec3b>(y);
      const double dy2 = (y - cy) * (y - cy);
      for (int x = 0; x < bgr.cols; ++x) {
        const float g = 1.0f - l.vignetting * static_cast<float>(((x - cx) * (x - cx) + dy2) * inv);
        for (int c = 0; c < 3; ++c) row[x][c] = cv::saturate_cast<uchar>(row[x][c] * g);
      }
    }
  }
  if (l.blur_sigma > 0.05f) cv::GaussianBlur(bgr, bgr, cv::Size(0, 0), l.blur_sigma);
  if (l.noise_sigma > 0) {
    cv::Mat noise(bgr.size(), CV_16SC3);
    cv::RNG rng(mix_seed(seed) | 1);
    rng.fill(noise, cv::RNG::NORMAL, 0, l.noise_sigma);
    cv::Mat wide;
    bgr.convertTo(wide, CV_16SC3);
    wide += noise;
    wide.convertTo(bgr, CV_8UC3);
  }
  if (l.jpeg_quality > 0) {
    std::vector<uchar> bytes;
    cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, l.jpeg_quality});
    bgr = cv::imdecode(bytes, cv::IMREAD_COLOR);
  }
}

}  // namespace fieldlines::synth
