#include "fieldlines/detect/intersections.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace fieldlines {
namespace {

using Junction = IntersectionWorkspace::Junction;
using Ray = IntersectionWorkspace::Ray;

constexpr float kReachFloorPx = 4;         // the edge detector's blur at a line's end
constexpr float kRayMergeCos = 0.9063f;    // cos(25 degrees): rays closer than this are one arm...
constexpr float kLongRayMergeCos = 0.9848f;  // cos(10 degrees): ...unless both are long arms
constexpr float kLongArmReaches = 3;       // a far corner's arms in perspective: this long and acute
constexpr float kStraightCos = -0.8660f;   // cos(150 degrees): two rays wider apart are one line
constexpr float kFullArmWidths = 6;        // an arm this many reaches long counts fully

struct Line {
  float x = 0, y = 0, ux = 0, uy = 0, length = 0, width = 0;
};

Line line_of(const Marking& m) {
  Line l{.x = m.x0, .y = m.y0, .width = m.width};
  const float dx = m.x1 - m.x0, dy = m.y1 - m.y0;
  l.length = std::hypot(dx, dy);
  if (l.length > 0) l.ux = dx / l.length, l.uy = dy / l.length;
  return l;
}

// Adds the arms of `l` leaving the crossing at `t` px along it: each side on which it extends
// beyond `reach`.
void add_arms(const Line& l, float t, float reach, Junction& j) {
  if (t > reach) j.rays[j.num_rays++] = {-l.ux, -l.uy, t};
  if (l.length - t > reach) j.rays[j.num_rays++] = {l.ux, l.uy, l.length - t};
}

// Folds `ray` into the junction's arm within 25 degrees of it (10 when both are long: a far
// corner seen in perspective is that acute, while a short stub beside an arm is the same line's
// or a curve's), or appends it.
void merge_ray(const Ray& ray, Junction& j) {
  for (int k = 0; k < j.num_rays; ++k) {
    Ray& r = j.rays[static_cast<std::size_t>(k)];
    const float n = std::hypot(r.ux, r.uy);
    const bool long_arms = std::min(r.length, ray.length) >= kLongArmReaches * j.reach;
    if ((r.ux * ray.ux + r.uy * ray.uy) / n < (long_arms ? kLongRayMergeCos : kRayMergeCos)) continue;
    // A length-weighted mean direction: the longer arm is the better measured.
    r.ux = r.ux / n * r.length + ray.ux * ray.length;
    r.uy = r.uy / n * r.length + ray.uy * ray.length;
    r.length = std::max(r.length, ray.length);
    return;
  }
  if (j.num_rays < static_cast<int>(j.rays.size())) j.rays[static_cast<std::size_t>(j.num_rays++)] = ray;
}

void merge_into(const Junction& c, Junction& j) {
  const float w = j.weight + c.weight;
  j.x = (j.x * j.weight + c.x * c.weight) / w;
  j.y = (j.y * j.weight + c.y * c.weight) / w;
  j.weight = w;
  j.reach = std::max(j.reach, c.reach);
  for (int k = 0; k < c.num_rays; ++k) merge_ray(c.rays[static_cast<std::size_t>(k)], j);
}

float heading(const Ray& r) {
  constexpr float two_pi = 2 * std::numbers::pi_v<float>;
  const float h = std::atan2(r.uy, r.ux);
  return h < 0 ? h + two_pi : (h >= two_pi ? 0.f : h);
}

// The Intersection of a merged junction, or false when it is no junction.
bool finish(Junction& j, Intersection& out) {
  auto* rays = j.rays.data();
  for (int k = 0; k < j.num_rays; ++k) {
    const float n = std::hypot(rays[k].ux, rays[k].uy);
    rays[k].ux /= n, rays[k].uy /= n;
  }
  std::sort(rays, rays + j.num_rays, [](const Ray& a, const Ray& b) { return a.length > b.length; });
  const int n = std::min(j.num_rays, 4);
  if (n < 2) return false;
  if (n == 2 && rays[0].ux * rays[1].ux + rays[0].uy * rays[1].uy < kStraightCos) return false;
  out = {.x = j.x, .y = j.y, .type = n == 2 ? JunctionType::L : (n == 3 ? JunctionType::T : JunctionType::X),
         .num_rays = n};
  float strength = 0;
  for (int k = 0; k < n; ++k) {
    out.heading_rays[static_cast<std::size_t>(k)] = heading(rays[k]);
    strength += std::min(1.f, rays[k].length / (kFullArmWidths * j.reach));
  }
  // Insertion sort of at most four: std::sort over a prefix of the array trips GCC 12's
  // -Warray-bounds.
  auto& h = out.heading_rays;
  for (std::size_t k = 1; k < static_cast<std::size_t>(n); ++k)
    for (std::size_t m = k; m > 0 && h[m - 1] > h[m]; --m) std::swap(h[m - 1], h[m]);
  out.confidence = strength / static_cast<float>(n);
  return true;
}

}  // namespace

const char* to_string(JunctionType type) {
  switch (type) {
    case JunctionType::L: return "L";
    case JunctionType::T: return "T";
    case JunctionType::X: return "X";
  }
  return "L";
}

void find_intersections(std::span<const Marking> markings, const DetectorParams& params,
                        IntersectionWorkspace& work, std::vector<Intersection>& out, cv::Size frame) {
  out.clear();
  work.junctions.clear();
  const float min_sin = static_cast<float>(std::sin(params.intersection_min_angle * std::numbers::pi / 180));
  const auto reach_of = [&](const Line& l) {
    return static_cast<float>(params.intersection_reach) * l.width + kReachFloorPx;
  };
  for (std::size_t a = 0; a < markings.size(); ++a) {
    const Line la = line_of(markings[a]);
    for (std::size_t b = a + 1; b < markings.size(); ++b) {
      const Line lb = line_of(markings[b]);
      const float cross = la.ux * lb.uy - la.uy * lb.ux;
      if (std::abs(cross) < min_sin) continue;
      // From the narrower line: a field's lines share one width, and a stripe's width measured
      // across blur or a merged edge can be several times its paint's.
      const float reach = std::min(reach_of(la), reach_of(lb));
      // A line shorter than two reaches could not tell ending from passing through.
      if (la.length < 2 * reach || lb.length < 2 * reach) continue;
      const float wx = lb.x - la.x, wy = lb.y - la.y;
      const float ta = (wx * lb.uy - wy * lb.ux) / cross;  // crossing, px along a from its start
      const float tb = (wx * la.uy - wy * la.ux) / cross;  // and along b from its start
      if (ta < -reach || ta > la.length + reach || tb < -reach || tb > lb.length + reach) continue;
      Junction c{.x = la.x + ta * la.ux, .y = la.y + ta * la.uy, .weight = 1, .reach = reach};
      add_arms(la, ta, reach, c);
      add_arms(lb, tb, reach, c);
      auto near = std::find_if(work.junctions.begin(), work.junctions.end(), [&](const Junction& j) {
        return std::hypot(j.x - c.x, j.y - c.y) <= std::max(j.reach, c.reach);
      });
      if (near != work.junctions.end()) {
        merge_into(c, *near);
      } else {
        Junction fresh = c;
        fresh.num_rays = 0;
        for (int k = 0; k < c.num_rays; ++k) merge_ray(c.rays[static_cast<std::size_t>(k)], fresh);
        work.junctions.push_back(fresh);
      }
    }
  }
  const bool clip = !frame.empty();
  for (Junction& j : work.junctions) {
    Intersection i;
    if (!finish(j, i)) continue;
    if (clip && !(i.x >= -0.5f && i.y >= -0.5f && i.x < frame.width - 0.5f && i.y < frame.height - 0.5f)) continue;
    out.push_back(i);
  }
}

}  // namespace fieldlines
