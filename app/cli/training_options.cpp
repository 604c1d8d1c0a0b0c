#include "app/cli/training_options.hpp"

#include <cstdio>

#include "app/cli/help_text.hpp"
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

std::string format_range(const Range& r) {
  char text[48];
  std::snprintf(text, sizeof text, "%g:%g", r.lo, r.hi);
  return text;
}

std::string on_off(bool on) { return on ? "on" : "off"; }

}  // namespace

std::string training_options_help() {
  const ProtocolSpec ours = protocol_spec(Protocol::Ours), paper = protocol_spec(Protocol::Paper);
  // "(ours X, paper Y)", or "(X)" when both protocols agree.
  const auto values = [&](auto get) {
    const std::string o = get(ours), p = get(paper);
    return o == p ? "(" + o + ")" : "(ours " + o + ", paper " + p + ")";
  };
  const auto number = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return std::string(text);
  };
  // In the 23-column margin of the commands' own options.
  const auto line = [](std::string& out, const char* option, const std::string& text) { out += help_row(option, text, 23); };
  std::string out;
  line(out, "--protocol P", "ours (default) or paper: sets all of the following, which then override");
  for (const Protocol p : {Protocol::Ours, Protocol::Paper})
    line(out, "", std::string(to_string(p)) + ": " + protocol_summary(p));
  line(out, "--class C", "marking, boundary or both " + values([](const ProtocolSpec& s) {
         return std::string(to_string(s.train.target));
       }));
  line(out, "--objective O", "tp-fp:C = TP - C FP, tp-fp (= tp-fp:1), f1 or fbeta:B " +
                                 values([](const ProtocolSpec& s) { return s.train.objective.name(); }));
  line(out, "--particles N", "PSO swarm size " + values([](const ProtocolSpec& s) {
         return std::to_string(s.train.pso.particles);
       }));
  line(out, "--iterations N", "PSO iterations " + values([](const ProtocolSpec& s) {
         return std::to_string(s.train.pso.iterations);
       }));
  line(out, "--inertia W", "PSO inertia " + values([&](const ProtocolSpec& s) { return number(s.train.pso.inertia); }));
  line(out, "--cognitive C", "PSO pull to a particle's own best " +
                                 values([&](const ProtocolSpec& s) { return number(s.train.pso.cognitive); }));
  line(out, "--social C", "PSO pull to the swarm's best " +
                              values([&](const ProtocolSpec& s) { return number(s.train.pso.social); }));
  line(out, "--polish on|off", "exact breakpoint polish after PSO " +
                                   values([](const ProtocolSpec& s) { return on_off(s.train.polish); }));
  line(out, "--projection-range LO:HI", "min projection search range " + values([](const ProtocolSpec& s) {
         return format_range(s.train.marking_bounds.projection);
       }));
  line(out, "--angle-range LO:HI", "max angle search range, degrees " + values([](const ProtocolSpec& s) {
         return format_range(s.train.marking_bounds.angle_deg);
       }));
  line(out, "--length-range LO:HI", "min length search range " + values([](const ProtocolSpec& s) {
         return format_range(s.train.marking_bounds.length);
       }));
  line(out, "--gradient G", "axes (default, the reference) or normal (orientation-invariant)");
  line(out, "--threads N", "threads scoring the swarm (1)");
  return out;
}

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
