#pragma once
// The camera file (`fieldlines detect --camera`, the Python module's set_camera): a fixed
// camera's intrinsics and pose over the turf (ground_camera.hpp), in degrees and metres.
//
//   {"format": "fieldlines-camera", "version": 1, "fx": 640, "fy": 640, "cx": 319.5, "cy": 239.5,
//    "pitch_deg": 30, "roll_deg": 0, "height_m": 0.6}
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/ground_camera.hpp"

namespace fieldlines {

// Throws fieldlines::Error "<where>: ..." naming the field that is missing, of the wrong type or
// out of range (validate()).
GroundCamera ground_camera_from_json(const nlohmann::json& j, const std::string& where);
nlohmann::json to_json(const GroundCamera& camera);
GroundCamera load_camera_file(const std::filesystem::path& path);

}  // namespace fieldlines
