#include "fieldlines/detect/camera_file.hpp"

#include <numbers>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/json_file.hpp"

namespace fieldlines {

namespace {
constexpr JsonFileFormat kFormat{"format", "fieldlines-camera", "camera file", "camera file", 1,
                                 JsonFileFormat::Newer::UpdateFieldlines};
constexpr double kDeg = std::numbers::pi / 180;
}  // namespace

GroundCamera ground_camera_from_json(const nlohmann::json& j, const std::string& where) {
  require_json_file_format(j, kFormat, where);
  const auto number = [&](const char* key) { return finite_field(json_field<double>(j, key, where), key, where); };
  const GroundCamera camera{.fx = number("fx"), .fy = number("fy"), .cx = number("cx"), .cy = number("cy"),
                            .pitch_rad = number("pitch_deg") * kDeg, .roll_rad = number("roll_deg") * kDeg,
                            .height_m = number("height_m")};
  try {
    validate(camera);
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
  return camera;
}

nlohmann::json to_json(const GroundCamera& c) {
  nlohmann::json j = json_file_header(kFormat);
  j.update({{"fx", c.fx}, {"fy", c.fy}, {"cx", c.cx}, {"cy", c.cy}, {"pitch_deg", c.pitch_rad / kDeg},
            {"roll_deg", c.roll_rad / kDeg}, {"height_m", c.height_m}});
  return j;
}

GroundCamera load_camera_file(const std::filesystem::path& path) {
  return ground_camera_from_json(parse_json_text(read_file(path), path.string()), path.string());
}

}  // namespace fieldlines
