#include "fieldlines/detect/ground_features_json.hpp"

#include <algorithm>
#include <cmath>

namespace fieldlines {
namespace {

// Six decimals (a micrometre): 2.500013 rather than 2.5000131234567; no more is known.
double rounded(double v) { return std::isfinite(v) ? std::round(v * 1e6) / 1e6 : 0.0; }

nlohmann::ordered_json point(double x, double y) { return {{"x", rounded(x)}, {"y", rounded(y)}, {"z", 0.0}}; }
nlohmann::ordered_json point(const GroundPoint& p) { return point(p.x, p.y); }
// Square metres to 1e-12 keep a centimetre's variance (1e-4) to eight digits.
nlohmann::ordered_json covariance(const GroundPoint& p) {
  nlohmann::ordered_json c = nlohmann::ordered_json::array();
  for (const double v : p.covariance) c.push_back(std::isfinite(v) ? std::round(v * 1e12) / 1e12 : 0.0);
  return c;
}

}  // namespace

nlohmann::ordered_json to_json(const GroundFeatures& ground) {
  nlohmann::ordered_json segments = nlohmann::ordered_json::array();
  for (const GroundMarkingSegment& s : ground.segments)
    segments.push_back({{"start", point(s.start)}, {"end", point(s.end)},
                        {"width", rounded(s.width)},
                        {"start_covariance", covariance(s.start)}, {"end_covariance", covariance(s.end)}});
  nlohmann::ordered_json intersections = nlohmann::ordered_json::array();
  for (const GroundIntersection& j : ground.intersections) {
    nlohmann::ordered_json rays = nlohmann::ordered_json::array();
    for (int k = 0; k < std::clamp(j.num_rays, 0, 4); ++k) {
      const auto& r = j.rays[static_cast<std::size_t>(k)];
      rays.push_back(point(r[0], r[1]));
    }
    intersections.push_back({{"center", point(j.center)}, {"center_covariance", covariance(j.center)},
                             {"type", to_string(j.type)}, {"num_rays", j.num_rays}, {"rays", std::move(rays)},
                             {"confidence", rounded(j.confidence)}});
  }
  nlohmann::ordered_json ellipses = nlohmann::ordered_json::array();
  for (const GroundEllipse& e : ground.ellipses)
    ellipses.push_back({{"center", {{"position", point(e.center)}, {"orientation", {{"x", 0.0}, {"y", 0.0}, {"z", 0.0}, {"w", 1.0}}}}},
                        {"diameter", rounded(e.diameter)},
                        {"center_covariance", covariance(e.center)},
                        {"confidence", rounded(e.confidence)}});
  nlohmann::ordered_json points = nlohmann::ordered_json::array(), covariances = nlohmann::ordered_json::array();
  for (const GroundPoint& p : ground.field_boundary) {
    points.push_back(point(p));
    covariances.push_back(covariance(p));
  }
  return {{"segments", std::move(segments)},
          {"intersections", std::move(intersections)},
          {"ellipses", std::move(ellipses)},
          {"field_boundary", {{"points", std::move(points)}, {"covariances", std::move(covariances)}}}};
}

}  // namespace fieldlines
