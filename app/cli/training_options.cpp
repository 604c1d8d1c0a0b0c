#include "app/cli/training_options.hpp"

#include "fieldlines/detect/error.hpp"

namespace fieldlines::cli {
namespace {

Range parse_range(const std::string& text, const std::string& what) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw Error(what + ": expected LO:HI, got '" + text + "'");
  Range r;
  r.lo = static_cast<float>(parse_double(text.substr(0, colon), what, -1e6, 1e6));
  r.hi = static_cast<float>(parse_double(text.substr(colon + 1), what, -1e6, 1e6));
  if (r.lo > r.hi) throw Error(what + ": LO must not exceed HI, got '" + text + "'");
  return r;
}

}  // namespace

const std::set<std::string>& training_value_options() {
  static const std::set<std::string> options = {
      "--protocol", "--class", "--objective", "--particles", "--iterations", "--inertia",
      "--cognitive", "--social", "--polish", "--projection-range", "--angle-range", "--length-range",
      "--gradient", "--threads"};
  return options;
}

ProtocolSpec apply_training_options(const ParsedArgs& a, Thresholds& start) {
  Protocol protocol = Protocol::Ours;
  if (const auto v = a.value("--protocol"); v && !parse_protocol(*v, protocol))
    throw Error("--protocol: expected ours or paper, got '" + *v + "'");
  ProtocolSpec spec = protocol_spec(protocol);
  TrainParams& t = spec.train;
  if (const auto v = a.value("--class"); v && !parse_train_class(*v, t.target))
    throw Error("--class: expected marking, boundary or both, got '" + *v + "'");
  if (const auto v = a.value("--objective")) t.objective = parse_objective(*v);
  t.pso.particles = a.int_or("--particles", t.pso.particles, 1, 100000);
  t.pso.iterations = a.int_or("--iterations", t.pso.iterations, 1, 1000000);
  t.pso.inertia = a.double_or("--inertia", t.pso.inertia, 0, 2);
  t.pso.cognitive = a.double_or("--cognitive", t.pso.cognitive, 0, 5);
  t.pso.social = a.double_or("--social", t.pso.social, 0, 5);
  if (const auto v = a.value("--polish")) {
    if (*v != "on" && *v != "off") throw Error("--polish: expected on or off, got '" + *v + "'");
    t.polish = *v == "on";
  }
  for (ThresholdBounds* b : {&t.marking_bounds, &t.boundary_bounds}) {
    if (const auto v = a.value("--projection-range")) b->projection = parse_range(*v, "--projection-range");
    if (const auto v = a.value("--angle-range")) b->angle_deg = parse_range(*v, "--angle-range");
    if (const auto v = a.value("--length-range")) b->length = parse_range(*v, "--length-range");
  }
  validate(t.marking_bounds);
  if (const auto v = a.value("--gradient")) {
    if (*v == "axes") start.mode = GradientMode::Axes;
    else if (*v == "normal") start.mode = GradientMode::Normal;
    else throw Error("--gradient: expected axes or normal, got '" + *v + "'");
  }
  t.threads = a.int_or("--threads", 1, 1, 256);
  return spec;
}

}  // namespace fieldlines::cli
