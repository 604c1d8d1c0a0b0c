#include "fieldlines/detect/steady_features.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

// The last frame's ground frame to this one's: the foot moved by (dx, dy) and turned by dyaw, so
// a point on the turf is (p - d) turned by -dyaw.
struct Turn {
  double c, s;
  explicit Turn(double yaw) : c(std::cos(yaw)), s(std::sin(yaw)) {}
  void vector(double& x, double& y) const {
    const double nx = c * x + s * y;
    y = -s * x + c * y;
    x = nx;
  }
};

void move(GroundPoint& p, const GroundMotion& m, const Turn& t) {
  p.x -= m.dx, p.y -= m.dy;
  t.vector(p.x, p.y);
  // The covariance turns with the frame: R C R^T.
  const double xx = p.covariance[0], xy = p.covariance[1], yy = p.covariance[2];
  const double c = t.c, s = t.s;
  p.covariance = {c * c * xx + 2 * c * s * xy + s * s * yy, (c * c - s * s) * xy + c * s * (yy - xx),
                  s * s * xx - 2 * c * s * xy + c * c * yy};
}
void move(GroundIntersection& j, const GroundMotion& m, const Turn& t) {
  move(j.center, m, t);
  for (auto& r : j.rays) t.vector(r[0], r[1]);
}
void move(GroundEllipse& e, const GroundMotion& m, const Turn& t) { move(e.center, m, t); }

GroundPoint& centre(GroundIntersection& j) { return j.center; }
GroundPoint& centre(GroundEllipse& e) { return e.center; }
const GroundPoint& centre(const GroundIntersection& j) { return j.center; }
const GroundPoint& centre(const GroundEllipse& e) { return e.center; }
bool same_kind(const GroundIntersection& a, const GroundIntersection& b) { return a.type == b.type; }
bool same_kind(const GroundEllipse&, const GroundEllipse&) { return true; }

// The observation's position, blended into the track's: the rest (rays, type, covariance,
// confidence, a circle's diameter blended too) is the observation's.
void blend(GroundIntersection& track, const GroundIntersection& seen, double a) {
  const GroundPoint old = track.center;
  track = seen;
  track.center.x = (1 - a) * old.x + a * seen.center.x;
  track.center.y = (1 - a) * old.y + a * seen.center.y;
}
void blend(GroundEllipse& track, const GroundEllipse& seen, double a) {
  const GroundEllipse old = track;
  track = seen;
  track.center.x = (1 - a) * old.center.x + a * seen.center.x;
  track.center.y = (1 - a) * old.center.y + a * seen.center.y;
  track.diameter = (1 - a) * old.diameter + a * seen.diameter;
}

// Moves the tracks, matches this frame's features to them (nearest first within `reach`, each
// track once), starts tracks for the rest, drops the stale, and writes them all to `out`.
template <class Track, class Feature>
void follow(std::vector<Track>& tracks, std::span<const Feature> seen, const GroundMotion& motion, double now,
            const SteadyParams& p, double reach, std::vector<Feature>& out) {
  const Turn turn(motion.dyaw);
  for (Track& t : tracks) {
    move(t.feature, motion, turn);
    t.matched = false;
  }
  const std::size_t old = tracks.size();
  for (const Feature& f : seen) {
    Track* best = nullptr;
    double best_d = reach;
    for (std::size_t k = 0; k < old; ++k) {
      Track& t = tracks[k];
      if (t.matched || !same_kind(t.feature, f)) continue;
      const double d = std::hypot(centre(t.feature).x - centre(f).x, centre(t.feature).y - centre(f).y);
      if (d <= best_d) best = &t, best_d = d;
    }
    if (best) {
      blend(best->feature, f, p.smoothing);
      best->last_seen_ms = now, best->matched = true;
    } else {
      tracks.push_back({f, now, true});
    }
  }
  std::erase_if(tracks, [&](const Track& t) { return now - t.last_seen_ms > p.hold_ms; });
  out.clear();
  for (const Track& t : tracks) {
    out.push_back(t.feature);
    if (!t.matched) {
      const double age = p.hold_ms > 0 ? (now - t.last_seen_ms) / p.hold_ms : 1;
      out.back().confidence *= static_cast<float>(std::clamp(1 - age, 0.0, 1.0));
    }
  }
}

}  // namespace

void validate(const SteadyParams& p) {
  if (!(p.hold_ms >= 0 && std::isfinite(p.hold_ms))) throw Error("steady features: hold_ms must be 0 or more milliseconds");
  if (!(p.match_m > 0 && std::isfinite(p.match_m) && p.circle_match_m > 0 && std::isfinite(p.circle_match_m)))
    throw Error("steady features: match_m and circle_match_m must be positive distances in metres");
  if (!(p.smoothing > 0 && p.smoothing <= 1)) throw Error("steady features: smoothing must lie in (0, 1]");
}

SteadyFeatures::SteadyFeatures(SteadyParams params) : params_(params) { validate(params_); }

void SteadyFeatures::reset() {
  junctions_.clear();
  circles_.clear();
  started_ = false;
}

const GroundFeatures& SteadyFeatures::update(const GroundFeatures& seen, double time_ms, const GroundMotion& motion) {
  if (!std::isfinite(time_ms)) throw Error("steady features: the frame's time must be a finite number of milliseconds");
  if (started_ && time_ms < last_ms_) reset();  // the clock went back: a new stream
  started_ = true;
  last_ms_ = time_ms;
  out_.segments.assign(seen.segments.begin(), seen.segments.end());
  out_.field_boundary.assign(seen.field_boundary.begin(), seen.field_boundary.end());
  follow(junctions_, std::span(seen.intersections), motion, time_ms, params_, params_.match_m, out_.intersections);
  follow(circles_, std::span(seen.ellipses), motion, time_ms, params_, params_.circle_match_m, out_.ellipses);
  return out_;
}

}  // namespace fieldlines
