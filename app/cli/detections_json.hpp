#pragma once
// The JSON that `fieldlines detect --json` writes (schema in docs/detect_and_bench.md):
// {"images":[{"image","path","width","height","detect_ms","segments":[{"x0","y0","x1","y1",
//  "saliency","grad_x":[r,g,b],"grad_y":[r,g,b],"label"}],"field_boundary":[[x,y],...],
//  "markings":[{"x0","y0","x1","y1","width"}],
//  "intersections":[{"x","y","type":"L"|"T"|"X","num_rays","heading_rays":[...],"confidence"}],
//  "ellipses":[{"cx","cy","width","height","angle_deg","confidence"}],
//  "ground": {...} (with a camera only: ground_features_json.hpp)}],
//  "errors":[{"path","error"}]}
// grad_y is the image-down derivative and channels are R,G,B, as in fieldlines::Segment.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/ground_features_json.hpp"
#include "fieldlines/detect/segment.hpp"
#include "app/cli/image_inputs.hpp"

namespace fieldlines::cli {

struct ImageDetections {
  std::filesystem::path path;
  int width = 0, height = 0;
  double detect_ms = 0;  // LineDetector::detect alone (decoding and drawing excluded)
  std::vector<Segment> segments;
  std::vector<FieldBoundary::Point> field_boundary;  // left to right; empty: no field seen
  std::vector<Marking> markings;  // stripes' centre lines (stripes.hpp); empty when the stage is off
  std::vector<Intersection> intersections;  // intersections.hpp; likewise
  std::vector<MarkingEllipse> ellipses;     // centre_circle.hpp; likewise
  std::optional<GroundFeatures> ground;     // ground_features.hpp; with a camera only
};

nlohmann::ordered_json to_json(const Segment& segment);
nlohmann::ordered_json to_json(const ImageDetections& image);
nlohmann::ordered_json detections_json(std::span<const ImageDetections> images, std::span<const FailedImage> failed);

}  // namespace fieldlines::cli
