#include "fieldlines/detect/params_json.hpp"

#include <cmath>
#include <type_traits>

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
    throw Error(where + "." + name + ": " + format_param_number(d) + " is outside " + ParamRange{lo, hi}.to_string());
  return d;
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
  json j = json::object();
  for (const ParamSpec& spec : kDetectorParamSpecs)
    if (spec.in_files) std::visit([&](auto member) { j[std::string(spec.name)] = p.*member; }, spec.member);
  return j;
}

DetectorParams detector_params_from_json(const json& j, const std::string& where) {
  if (!j.is_object()) throw Error(where + ": expected an object");
  DetectorParams p;
  for (const ParamSpec& spec : kDetectorParamSpecs) {
    const std::string key(spec.name);
    const auto it = j.find(key);
    if (!spec.in_files || it == j.end()) continue;  // missing fields keep their defaults
    const std::string field = where + "." + key;
    // Range errors name the field, the value and the range, from the same table validate() reads.
    const auto in_range = [&](const std::string& name, double v) {
      if (const auto why = param_error(spec, v)) throw Error(name + ": " + *why);
    };
    const auto integer = [&](const json& v, const std::string& name) {
      if (!v.is_number_integer()) throw Error(name + ": expected an integer");
      const auto i = v.get<long long>();
      in_range(name, static_cast<double>(i));
      return static_cast<int>(i);
    };
    std::visit(
        [&](auto member) {
          auto& out = p.*member;
          using T = std::decay_t<decltype(out)>;
          if constexpr (std::is_same_v<T, bool>) {
            if (!it->is_boolean()) throw Error(field + ": expected true or false");
            out = it->template get<bool>();
          } else if constexpr (std::is_same_v<T, int>) {
            out = integer(*it, field);
          } else if constexpr (std::is_same_v<T, double>) {
            if (!it->is_number()) throw Error(field + ": expected a number");
            out = it->template get<double>();
            in_range(field, out);
          } else {
            if (!it->is_array()) throw Error(field + ": expected an array of integers");
            out.clear();
            for (std::size_t i = 0; i < it->size(); ++i)
              out.push_back(integer((*it)[i], field + "[" + std::to_string(i) + "]"));
          }
        },
        spec.member);
  }
  return p;
}

json thresholds_to_json(const Thresholds& t) {
  json j{{"gradient_mode", t.mode == GradientMode::Normal ? "normal" : "axes"},
         {"reference_pi", t.reference_pi},
         {"classes", {{"boundary", class_to_json(t.boundary)}, {"marking", class_to_json(t.marking)}}}};
  // Only when on: files without it read as before.
  if (t.light.enabled) j["light"] = {{"adapt", true}, {"reference_field", t.light.reference_field}};
  if (t.field_boundary_gate) j["field_boundary"] = {{"gate", true}};
  return j;
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
  if (j.contains("light")) {
    const json& light = j["light"];
    if (!light.is_object()) throw Error(where + ".light: expected an object");
    t.light.enabled = boolean(light, "adapt", where + ".light");
    t.light.reference_field = rgb(light, "reference_field", where + ".light");
    if (t.light.enabled && !(t.light.reference_field[1] > 0))
      throw Error(where + ".light.reference_field: the field's green must be above 0");
  }
  if (j.contains("field_boundary")) {
    const json& fb = j["field_boundary"];
    if (!fb.is_object()) throw Error(where + ".field_boundary: expected an object");
    t.field_boundary_gate = boolean(fb, "gate", where + ".field_boundary");
  }
  return t;
}

}  // namespace fieldlines
