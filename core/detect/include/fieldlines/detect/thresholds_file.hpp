#pragma once
// The file the robot loads: detector parameters, per class colour transition, sidedness and
// thresholds, and how they were obtained. Schema (version 1):
//   { "format": "fieldlines-thresholds", "version": 1,
//     "detector": { DetectorParams fields },
//     "gradient_mode": "axes" | "normal", "reference_pi": false,
//     "classes": { "boundary": {"from": [R,G,B], "to": [R,G,B], "two_sided": false,
//                               "min_projection": p, "max_angle_deg": a, "min_length": l},
//                  "marking": { same } },
//     "light": {"adapt": true, "reference_field": [R,G,B]}     optional (light.hpp)
//     "field_boundary": {"gate": true}                         optional (field_boundary.hpp)
//     "provenance": { free-form object; `fieldlines train` writes data files, counts,
//                     objective, seed, date and "train"/"test" metrics per class } }
#include <filesystem>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector.hpp"

namespace fieldlines {

inline constexpr int kThresholdsFileVersion = 1;

struct ThresholdsFile {
  DetectorParams detector;
  Thresholds thresholds;
  nlohmann::json provenance = nlohmann::json::object();
};

nlohmann::json to_json(const ThresholdsFile& file);
// Validates format, version (newer versions are rejected with a clear message) and ranges;
// `where` names the source in error messages.
ThresholdsFile thresholds_file_from_json(const nlohmann::json& j, const std::string& where);

// Throws fieldlines::Error naming the path on unreadable, malformed or out-of-range content.
ThresholdsFile load_thresholds_file(const std::filesystem::path& path);
// Atomic (temp file + rename).
void save_thresholds_file(const std::filesystem::path& path, const ThresholdsFile& file);

}  // namespace fieldlines
