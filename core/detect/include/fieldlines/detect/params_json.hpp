#pragma once
// JSON forms of DetectorParams and Thresholds shared by the thresholds file and the project
// file. Readers validate every field and throw fieldlines::Error naming `where` and the field.
#include <string>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector_params.hpp"

namespace fieldlines {

nlohmann::json detector_params_to_json(const DetectorParams& p);
// Missing fields keep their defaults; present ones must have the right type and the range of
// kDetectorParamSpecs. Keys the table does not name are ignored.
DetectorParams detector_params_from_json(const nlohmann::json& j, const std::string& where);

// {"gradient_mode", "reference_pi", "classes": {"boundary": {...}, "marking": {...}}}, each class
// with from/to RGB, two_sided, min_projection, max_angle_deg, min_length.
nlohmann::json thresholds_to_json(const Thresholds& t);
// Every class field is required; ranges: RGB in [0, 1] or [0, 255] (not both zero-length), min
// projection in [-1000, 1000], max angle in [0, 180], min length in [0, 100000].
Thresholds thresholds_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace fieldlines
