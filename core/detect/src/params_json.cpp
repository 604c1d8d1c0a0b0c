#include "fieldlines/detect/params_json.hpp"

#include <cmath>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

using nlohmann::json;

const json& field(const json& j, const char* name, const std::string& where) {
  if (!j.is_object()) throw Error(where + ": expected an object");
  const auto it = j.find(name);
  if (it == j.end()) throw Error(where + ": missing field '" + name + "'");
  return *it;
}

double number(const json& j, const char* name, const std::string& where, double lo, double hi) {
  const json& v = field(j, name, where);
  if (!v.is_number()) throw Error(where + "." + name + ": expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d) || d < lo || d > hi)
    throw Error(where + "." + name + ": " + std::to_string(d) + " is outside [" + std::to_string(lo) +
                ", " + std::to_string(hi) + "]");
  return d;
}

int integer(const json& j, const char* name, const std::string& where, int lo, int hi) {
  const json& v = field(j, name, where);
  if (!v.is_number_integer()) throw Error(where + "." + name + ": expected an integer");
  const auto i = v.get<long long>();
  if (i < lo || i > hi)
    throw Error(where + "." + name + ": " + std::to_string(i) + " is outside [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "]");
  return static_cast<int>(i);
}

bool boolean(const json& j, const char* name, const std::string& where) {
  const json& v = field(j, name, where);
  if (!v.is_boolean()) throw Error(where + "." + name + ": expected true or false");
  return v.get<bool>();
}

Rgb rgb(const json& j, const char* name, const std::string& where) {
  const json& v = field(j, name, where);
  if (!v.is_array() || v.size() != 3) throw Error(where + "." + name + ": expected [R, G, B]");
  Rgb c{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!v[i].is_number()) throw Error(where + "." + name + ": expected [R, G, B] numbers");
    c[i] = v[i].get<float>();
    if (!std::isfinite(c[i]) || c[i] < 0 || c[i] > 255)
      throw Error(where + "." + name + ": channels must be in [0, 255]");
  }
  return c;
}

json class_to_json(const ColourClass& c) {
  return {{"from", c.from},
          {"to", c.to},
          {"two_sided", c.two_sided},
          {"min_projection", c.thresholds.min_projection},
          {"max_angle_deg", c.thresholds.max_angle_deg},
          {"min_length", c.thresholds.min_length}};
}

ColourClass class_from_json(const json& j, const std::string& where) {
  ColourClass c;
  c.from = rgb(j, "from", where);
  c.to = rgb(j, "to", where);
  if (c.from == c.to) throw Error(where + ": 'from' and 'to' colours must differ");
  c.two_sided = boolean(j, "two_sided", where);
  c.thresholds.min_projection = static_cast<float>(number(j, "min_projection", where, -1000, 1000));
  c.thresholds.max_angle_deg = static_cast<float>(number(j, "max_angle_deg", where, 0, 180));
  c.thresholds.min_length = static_cast<float>(number(j, "min_length", where, 0, 100000));
  return c;
}

}  // namespace

json detector_params_to_json(const DetectorParams& p) {
  return {{"gaussian_kernel", p.gaussian_kernel},
          {"gaussian_sigma", p.gaussian_sigma},
          {"gradient_threshold", p.gradient_threshold},
          {"anchor_threshold", p.anchor_threshold},
          {"scan_interval", p.scan_interval},
          {"min_line_length", p.min_line_length},
          {"line_fit_error", p.line_fit_error},
          {"px_to_segment_dist", p.px_to_segment_dist},
          {"validation_threshold", p.validation_threshold},
          {"validate", p.validate},
          {"treat_junctions", p.treat_junctions},
          {"junction_sizes", p.junction_sizes}};
}

DetectorParams detector_params_from_json(const json& j, const std::string& where) {
  if (!j.is_object()) throw Error(where + ": expected an object");
  DetectorParams p;
  const auto has = [&](const char* n) { return j.contains(n); };
  constexpr int kBig = 1 << 20;
  if (has("gaussian_kernel")) p.gaussian_kernel = integer(j, "gaussian_kernel", where, 0, 99);
  if (has("gaussian_sigma")) p.gaussian_sigma = number(j, "gaussian_sigma", where, 0, 100);
  if (has("gradient_threshold")) p.gradient_threshold = integer(j, "gradient_threshold", where, 0, kBig);
  if (has("anchor_threshold")) p.anchor_threshold = integer(j, "anchor_threshold", where, 0, kBig);
  if (has("scan_interval")) p.scan_interval = integer(j, "scan_interval", where, 1, kBig);
  if (has("min_line_length")) p.min_line_length = integer(j, "min_line_length", where, 0, kBig);
  if (has("line_fit_error")) p.line_fit_error = number(j, "line_fit_error", where, 0, 1e6);
  if (has("px_to_segment_dist")) p.px_to_segment_dist = number(j, "px_to_segment_dist", where, 0, 1e6);
  if (has("validation_threshold")) p.validation_threshold = number(j, "validation_threshold", where, 0, 10);
  if (has("validate")) p.validate = boolean(j, "validate", where);
  if (has("treat_junctions")) p.treat_junctions = boolean(j, "treat_junctions", where);
  if (has("junction_sizes")) {
    const json& v = j["junction_sizes"];
    if (!v.is_array()) throw Error(where + ".junction_sizes: expected an array of integers");
    p.junction_sizes.clear();
    for (const json& e : v) {
      if (!e.is_number_integer()) throw Error(where + ".junction_sizes: expected integers");
      p.junction_sizes.push_back(e.get<int>());
    }
  }
  try {
    validate(p);
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
  return p;
}

json thresholds_to_json(const Thresholds& t) {
  return {{"gradient_mode", t.mode == GradientMode::Normal ? "normal" : "axes"},
          {"reference_pi", t.reference_pi},
          {"classes", {{"boundary", class_to_json(t.boundary)}, {"marking", class_to_json(t.marking)}}}};
}

Thresholds thresholds_from_json(const json& j, const std::string& where) {
  Thresholds t;
  const json& mode = field(j, "gradient_mode", where);
  if (mode == "axes") t.mode = GradientMode::Axes;
  else if (mode == "normal") t.mode = GradientMode::Normal;
  else throw Error(where + ".gradient_mode: expected \"axes\" or \"normal\"");
  t.reference_pi = j.contains("reference_pi") ? boolean(j, "reference_pi", where) : false;
  const json& classes = field(j, "classes", where);
  t.boundary = class_from_json(field(classes, "boundary", where + ".classes"), where + ".classes.boundary");
  t.marking = class_from_json(field(classes, "marking", where + ".classes"), where + ".classes.marking");
  return t;
}

}  // namespace fieldlines
