#include "fieldlines/synth/ground_score.hpp"

#include <cmath>
#include <limits>

namespace fieldlines::synth {

GroundScore& GroundScore::operator+=(const GroundScore& o) {
  junction_error_share.insert(junction_error_share.end(), o.junction_error_share.begin(), o.junction_error_share.end());
  junction_distance_m.insert(junction_distance_m.end(), o.junction_distance_m.begin(), o.junction_distance_m.end());
  circle_error_m.insert(circle_error_m.end(), o.circle_error_m.begin(), o.circle_error_m.end());
  near_circles += o.near_circles;
  return *this;
}

GroundScore score_ground(const FeatureTruth& truth, const FieldFeatures& detected, const GroundFeatures& detected_ground,
                         const GroundCamera& given, const GroundCamera& truth_camera, const FeatureScoreParams& params,
                         const GroundScoreParams& ground) {
  GroundScore s;
  const GroundProjection seen(given), exact(truth_camera);
  for (const auto& [det, tru] : matched_junctions(truth, detected, params)) {
    const Intersection &d = detected.intersections[det], &t = truth.intersections[tru];
    const auto dg = seen.to_ground(d.x, d.y), tg = exact.to_ground(t.x, t.y);
    if (!dg || !tg) continue;  // at the horizon: never projected
    const double distance = std::hypot(tg->x, tg->y);
    s.junction_error_share.push_back(std::hypot(dg->x - tg->x, dg->y - tg->y) / distance);
    s.junction_distance_m.push_back(distance);
  }
  if (!truth.circle || truth.circle->visible_share < params.min_circle_share) return s;
  FieldFeatures circle_only;
  circle_only.ellipses.push_back(truth.circle->ellipse);
  GroundFeatures true_circle;
  GroundFeatureParams reach;
  reach.max_distance_m = std::numeric_limits<double>::max();
  project_features(circle_only, truth_camera, reach, true_circle);
  if (true_circle.ellipses.empty()) return s;
  const GroundPoint& c = true_circle.ellipses[0].center;
  if (std::hypot(c.x, c.y) > ground.max_circle_distance_m) return s;
  ++s.near_circles;
  double best = std::numeric_limits<double>::infinity();
  for (const GroundEllipse& e : detected_ground.ellipses)
    best = std::min(best, std::hypot(e.center.x - c.x, e.center.y - c.y));
  if (std::isfinite(best)) s.circle_error_m.push_back(best);
  return s;
}

}  // namespace fieldlines::synth
