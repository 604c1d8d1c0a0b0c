#include "app/cli/detections_json.hpp"

#include <algorithm>

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace fieldlines::cli {
namespace {

// The double nearest the float's shortest decimal form, so the file shows -0.98697948 rather
// than -0.9869794845581055 and still reads back to the same float. NaN/inf are not JSON: the
// detector must not produce them, but never write an unreadable file.
double finite_or_zero(float v) {
  if (!std::isfinite(v)) return 0.0;
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  *end = '\0';
  return std::strtod(buf, nullptr);
}

nlohmann::ordered_json rgb(const Rgb& c) {
  return nlohmann::ordered_json::array({finite_or_zero(c[0]), finite_or_zero(c[1]), finite_or_zero(c[2])});
}

}  // namespace

nlohmann::ordered_json to_json(const Segment& s) {
  return {{"x0", finite_or_zero(s.x0)},           {"y0", finite_or_zero(s.y0)},
          {"x1", finite_or_zero(s.x1)},           {"y1", finite_or_zero(s.y1)},
          {"saliency", finite_or_zero(s.saliency)}, {"grad_x", rgb(s.grad_x)},
          {"grad_y", rgb(s.grad_y)},              {"label", std::string(to_string(s.label))}};
}

nlohmann::ordered_json to_json(const ImageDetections& image) {
  nlohmann::ordered_json segments = nlohmann::ordered_json::array();
  for (const Segment& s : image.segments) segments.push_back(to_json(s));
  nlohmann::ordered_json boundary = nlohmann::ordered_json::array();
  for (const FieldBoundary::Point& p : image.field_boundary)
    boundary.push_back(nlohmann::ordered_json::array({finite_or_zero(p.x), finite_or_zero(p.y)}));
  // Keys as soccer_vision_2d_msgs' MarkingSegment, MarkingIntersection and MarkingEllipse name
  // them; other tools read them.
  nlohmann::ordered_json markings = nlohmann::ordered_json::array();
  for (const Marking& m : image.markings)
    markings.push_back({{"x0", finite_or_zero(m.x0)}, {"y0", finite_or_zero(m.y0)}, {"x1", finite_or_zero(m.x1)},
                        {"y1", finite_or_zero(m.y1)}, {"width", finite_or_zero(m.width)}});
  nlohmann::ordered_json intersections = nlohmann::ordered_json::array();
  for (const Intersection& j : image.intersections) {
    nlohmann::ordered_json rays = nlohmann::ordered_json::array();
    for (int k = 0; k < std::clamp(j.num_rays, 0, 4); ++k) rays.push_back(finite_or_zero(j.heading_rays[static_cast<std::size_t>(k)]));
    intersections.push_back({{"x", finite_or_zero(j.x)}, {"y", finite_or_zero(j.y)}, {"type", to_string(j.type)},
                             {"num_rays", j.num_rays}, {"heading_rays", std::move(rays)},
                             {"confidence", finite_or_zero(j.confidence)}});
  }
  nlohmann::ordered_json ellipses = nlohmann::ordered_json::array();
  for (const MarkingEllipse& e : image.ellipses)
    ellipses.push_back({{"cx", finite_or_zero(e.cx)}, {"cy", finite_or_zero(e.cy)}, {"width", finite_or_zero(e.width)},
                        {"height", finite_or_zero(e.height)}, {"angle_deg", finite_or_zero(e.angle_deg)},
                        {"confidence", finite_or_zero(e.confidence)}});
  nlohmann::ordered_json out{{"image", image.path.filename().string()},
          {"path", image.path.string()},
          {"width", image.width},
          {"height", image.height},
          {"detect_ms", image.detect_ms},
          {"segments", std::move(segments)},
          {"field_boundary", std::move(boundary)},
          {"markings", std::move(markings)},
          {"intersections", std::move(intersections)},
          {"ellipses", std::move(ellipses)}};
  if (image.ground) out["ground"] = to_json(*image.ground);
  return out;
}

nlohmann::ordered_json detections_json(std::span<const ImageDetections> images, std::span<const FailedImage> failed) {
  nlohmann::ordered_json out{{"images", nlohmann::ordered_json::array()}, {"errors", nlohmann::ordered_json::array()}};
  for (const auto& image : images) out["images"].push_back(to_json(image));
  for (const auto& f : failed) out["errors"].push_back({{"path", f.path.string()}, {"error", f.error}});
  return out;
}

}  // namespace fieldlines::cli
