// The detector parameter table: it covers every DetectorParams field, its defaults are
// DetectorParams{}'s and valid, and every out-of-range value is refused, with the field, the
// value and the range named, by validate() and by the JSON reader alike.
#include <cmath>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/params_json.hpp"

namespace fieldlines {
namespace {

// How many initialisers DetectorParams takes: its field count (it is an aggregate).
struct AnyValue {
  template <class T>
  operator T() const;  // NOLINT: converts to any field type, only in unevaluated contexts
};
template <class T, std::size_t... I>
constexpr bool takes(std::index_sequence<I...>) {
  return requires { T{(static_cast<void>(I), AnyValue{})...}; };
}
template <class T, std::size_t N = 0>
constexpr std::size_t field_count() {
  if constexpr (!takes<T>(std::make_index_sequence<N + 1>{})) return N;
  else return field_count<T, N + 1>();
}

bool is_flag(const ParamSpec& s) { return std::holds_alternative<bool DetectorParams::*>(s.member); }
bool is_int(const ParamSpec& s) {
  return std::holds_alternative<int DetectorParams::*>(s.member) ||
         std::holds_alternative<std::vector<int> DetectorParams::*>(s.member);
}

// `params` with the field of `spec` set to `v` (a list: {v}).
DetectorParams with_value(const ParamSpec& spec, double v) {
  DetectorParams p;
  std::visit(
      [&](auto member) {
        using T = std::decay_t<decltype(p.*member)>;
        if constexpr (std::is_same_v<T, std::vector<int>>) p.*member = {static_cast<int>(v)};
        else if constexpr (std::is_same_v<T, int>) p.*member = static_cast<int>(v);
        else if constexpr (std::is_same_v<T, double>) p.*member = v;
      },
      spec.member);
  return p;
}

nlohmann::json json_value(const ParamSpec& spec, double v) {
  if (std::holds_alternative<std::vector<int> DetectorParams::*>(spec.member))
    return nlohmann::json::array({static_cast<long long>(v)});
  if (is_int(spec)) return static_cast<long long>(v);
  return v;
}

// Values just outside the spec's range (and an even kernel size).
std::vector<double> out_of_range(const ParamSpec& s) {
  const double step = is_int(s) ? 1 : 1e-3;
  std::vector<double> v{s.range.lo_open ? s.range.lo : s.range.lo - step, s.range.hi + step};
  if (s.odd) v.push_back(4);
  return v;
}

std::string error_of(const auto& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DetectorParamsTable, NamesEveryFieldOnce) {
  EXPECT_EQ(kDetectorParamSpecs.size(), field_count<DetectorParams>())
      << "a DetectorParams field has no entry in kDetectorParamSpecs";
  std::set<std::string> names;
  for (const ParamSpec& s : kDetectorParamSpecs) {
    EXPECT_TRUE(names.insert(std::string(s.name)).second) << s.name;
    for (const ParamSpec& other : kDetectorParamSpecs) {
      if (&other != &s) {
        EXPECT_NE(other.member, s.member) << s.name << " shares its field with " << other.name;
      }
    }
    EXPECT_FALSE(s.help.empty()) << s.name;
    EXPECT_EQ(find_param_spec(s.name), &s);
    EXPECT_EQ(is_flag(s), s.range.empty()) << s.name << ": a number needs a range, a flag none";
  }
  EXPECT_EQ(find_param_spec("no_such_parameter"), nullptr);
}

TEST(DetectorParamsTable, DefaultsAreDetectorParamsDefaultsAndValid) {
  const DetectorParams defaults;
  EXPECT_NO_THROW(validate(defaults));
  const nlohmann::json written = detector_params_to_json(defaults);
  EXPECT_EQ(detector_params_from_json(nlohmann::json::object(), "f"), defaults);
  for (const ParamSpec& s : kDetectorParamSpecs) {
    SCOPED_TRACE(std::string(s.name));
    // The text the help prints is the struct's value.
    std::visit(
        [&](auto member) {
          const auto& v = defaults.*member;
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool>) {
            EXPECT_EQ(param_default_text(s), v ? "true" : "false");
          } else if constexpr (std::is_same_v<T, std::vector<int>>) {
            ASSERT_FALSE(v.empty());
            EXPECT_EQ(param_default_text(s).find(std::to_string(v.front())), 0u);
            for (const int e : v) EXPECT_FALSE(param_error(s, e));
          } else {
            EXPECT_DOUBLE_EQ(std::stod(param_default_text(s)), static_cast<double>(v));
            EXPECT_FALSE(param_error(s, static_cast<double>(v))) << *param_error(s, static_cast<double>(v));
            if (!s.slider.empty()) {
              EXPECT_TRUE(s.slider.contains(static_cast<double>(v))) << "the slider cannot show the default";
              EXPECT_TRUE(s.range.contains(s.slider.lo) && s.range.contains(s.slider.hi))
                  << "the slider reaches invalid values";
            }
          }
        },
        s.member);
    // Files hold every parameter but the speed-only one, with the default's value.
    EXPECT_EQ(written.contains(std::string(s.name)), s.in_files);
  }
}

TEST(DetectorParamsTable, EveryOutOfRangeValueIsRefusedByValidateAndByTheJsonReader) {
  int checked = 0;
  for (const ParamSpec& s : kDetectorParamSpecs) {
    if (is_flag(s)) continue;
    for (const double v : out_of_range(s)) {
      SCOPED_TRACE(std::string(s.name) + " = " + format_param_number(v));
      const std::string value = format_param_number(v);
      const std::string why = s.odd && v == 4 ? "even" : s.range.to_string();
      // validate(): "detector parameter <name>: <value> is outside <range>".
      const std::string direct = error_of([&] { validate(with_value(s, v)); });
      EXPECT_NE(direct.find("detector parameter " + std::string(s.name)), std::string::npos) << direct;
      EXPECT_NE(direct.find(value), std::string::npos) << direct;
      EXPECT_NE(direct.find(why), std::string::npos) << direct;
      EXPECT_THROW(LineDetector{with_value(s, v)}, Error);
      ++checked;
      if (!s.in_files) continue;
      // The reader: "<where>.<name>: <value> is outside <range>", before any detector is built.
      nlohmann::json j = detector_params_to_json(DetectorParams{});
      j[std::string(s.name)] = json_value(s, v);
      const std::string read = error_of([&] { (void)detector_params_from_json(j, "f.json: detector"); });
      EXPECT_NE(read.find("f.json: detector." + std::string(s.name)), std::string::npos) << read;
      EXPECT_NE(read.find(value), std::string::npos) << read;
      EXPECT_NE(read.find(why), std::string::npos) << read;
    }
  }
  EXPECT_GE(checked, 2 * 10);
}

TEST(DetectorParamsTable, RangeEndsAreAcceptedWhereClosed) {
  for (const ParamSpec& s : kDetectorParamSpecs) {
    if (is_flag(s)) continue;
    SCOPED_TRACE(std::string(s.name));
    const double hi = s.odd && std::fmod(s.range.hi, 2) == 0 ? s.range.hi - 1 : s.range.hi;
    EXPECT_NO_THROW(validate(with_value(s, hi)));
    if (!s.range.lo_open) {
      EXPECT_NO_THROW(validate(with_value(s, s.range.lo)));
    }
    if (!s.in_files) continue;
    nlohmann::json j = nlohmann::json::object();
    j[std::string(s.name)] = json_value(s, hi);
    EXPECT_EQ(detector_params_from_json(j, "f"), with_value(s, hi));
  }
}

TEST(DetectorParamsTable, NotANumberAndWrongTypesAreRefused) {
  for (const ParamSpec& s : kDetectorParamSpecs) {
    if (!std::holds_alternative<double DetectorParams::*>(s.member)) continue;
    const std::string e = error_of([&] { validate(with_value(s, std::nan(""))); });
    EXPECT_NE(e.find(std::string(s.name) + ": nan is outside"), std::string::npos) << e;
  }
  const auto read_error = [](const char* key, nlohmann::json value) {
    return error_of([&] { (void)detector_params_from_json({{key, std::move(value)}}, "f"); });
  };
  EXPECT_NE(read_error("gaussian_kernel", 7.5).find("f.gaussian_kernel: expected an integer"), std::string::npos);
  EXPECT_NE(read_error("gaussian_sigma", "1").find("f.gaussian_sigma: expected a number"), std::string::npos);
  EXPECT_NE(read_error("validate", 1).find("f.validate: expected true or false"), std::string::npos);
  EXPECT_NE(read_error("junction_sizes", 5).find("expected an array of integers"), std::string::npos);
  EXPECT_NE(read_error("junction_sizes", nlohmann::json::array({5, 0})).find("f.junction_sizes[1]: 0 is outside [1, 100]"),
            std::string::npos);
  // Beyond int: refused as out of range, never wrapped into one.
  EXPECT_NE(read_error("scan_interval", 1LL << 40).find("f.scan_interval: 1.09951e+12 is outside [1, 1000]"),
            std::string::npos);
}

TEST(DetectorParamsTable, SpeedOnlyThreadsStayOutOfFiles) {
  DetectorParams p;
  p.threads = 4;
  EXPECT_FALSE(detector_params_to_json(p).contains("threads"));
  EXPECT_EQ(detector_params_from_json({{"threads", 4}}, "f").threads, 1);
}

}  // namespace
}  // namespace fieldlines
