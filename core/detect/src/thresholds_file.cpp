#include "fieldlines/detect/thresholds_file.hpp"

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/json_file.hpp"
#include "fieldlines/detect/params_json.hpp"

namespace fieldlines {

using nlohmann::json;

namespace {
constexpr JsonFileFormat kFormat{"format", "fieldlines-thresholds", "thresholds file", "thresholds file",
                                 kThresholdsFileVersion, JsonFileFormat::Newer::UpdateFieldlines};
}  // namespace

json to_json(const ThresholdsFile& f) {
  json j = json_file_header(kFormat);
  j["detector"] = detector_params_to_json(f.detector);
  j.update(thresholds_to_json(f.thresholds));
  j["provenance"] = f.provenance.is_null() ? json::object() : f.provenance;
  return j;
}

ThresholdsFile thresholds_file_from_json(const json& j, const std::string& where) {
  require_json_file_format(j, kFormat, where);
  ThresholdsFile f;
  if (!j.contains("detector")) throw Error(where + ": missing field 'detector'");
  f.detector = detector_params_from_json(j["detector"], where + ": detector");
  f.thresholds = thresholds_from_json(j, where);
  if (j.contains("provenance")) {
    if (!j["provenance"].is_object()) throw Error(where + ": 'provenance' must be an object");
    f.provenance = j["provenance"];
  }
  return f;
}

ThresholdsFile load_thresholds_file(const std::filesystem::path& path) {
  const json j = parse_json_text(read_file(path), path.string());
  return thresholds_file_from_json(j, path.string());
}

void save_thresholds_file(const std::filesystem::path& path, const ThresholdsFile& file) {
  write_file_atomically(path, to_json(file).dump(2) + "\n");
}

}  // namespace fieldlines
