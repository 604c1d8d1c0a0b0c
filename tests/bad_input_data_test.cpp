// Bad-input matrix, data files: reference CSV and project files for train, eval and sweep,
// thresholds files for detect, eval, autolabel and train's output. The readers' own messages are
// tested in reference_csv_test, dataset_test and thresholds_file_test; these check that every
// command passes them on with the file, exits 2 and writes nothing.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "bad_input_support.hpp"

namespace fs = std::filesystem;
using fieldlines::test::BadInputTest;
using fieldlines::test::kCsvHeader;
using fieldlines::test::read_text;
using json = nlohmann::json;

namespace {

const std::string kGoodRow = "a.png,0,0,5,5,1,2,3,4,5,6,7,False,True,False\n";

class BadData : public BadInputTest {
 protected:
  // Runs train, eval and sweep on `data`; each must exit 2 with every one of `parts` on stderr
  // and leave no output file.
  void expect_all_refuse(const fs::path& data, const std::vector<std::string>& parts) {
    const fs::path t = thresholds("t.json");
    const std::vector<std::vector<std::string>> commands = {
        {"train", data.string(), "--quiet", "--iterations", "5", "-o", path("out.json").string()},
        {"eval", data.string(), "--thresholds", t.string(), "--json", path("out.json").string()},
        {"sweep", data.string(), "--quiet", "--seeds", "1", "--fractions", "0.5", "--iterations", "5", "--json",
         path("out.json").string()}};
    for (const auto& c : commands) {
      SCOPED_TRACE(c.front());
      const auto r = run(c);
      EXPECT_EQ(r.exit_code, 2) << r.err;
      EXPECT_NE(r.err.find("fieldlines " + c.front() + ": error: "), std::string::npos) << r.err;
      for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << "missing '" << p << "' in:\n" << r.err;
      EXPECT_FALSE(fs::exists(path("out.json")));
    }
  }
  fs::path csv_text(const std::string& name, const std::string& body) { return bytes(name, kCsvHeader + body); }
};

// ---- reference CSV: train, eval, sweep -------------------------------------------------------

TEST_F(BadData, CsvMissingFile) { expect_all_refuse(path("none.csv"), {"none.csv", "not a file"}); }

TEST_F(BadData, CsvEmptyFile) { expect_all_refuse(bytes("empty.csv", ""), {"empty.csv"}); }

TEST_F(BadData, CsvMissingColumnInHeader) {
  expect_all_refuse(bytes("h.csv", "img_path,x0,y0,x1,y1,grad_Bx\n" + kGoodRow), {"h.csv:1"});
}

TEST_F(BadData, CsvRowWithTooFewFields) {
  expect_all_refuse(csv_text("short.csv", kGoodRow + "a.png,0,0,5,5,1,2,3\n"), {"short.csv:3"});
}

TEST_F(BadData, CsvWrongTypeInNumberColumn) {
  expect_all_refuse(csv_text("type.csv", kGoodRow + "a.png,0,0,5,5,1,two,3,4,5,6,7,False,True,False\n"),
                    {"type.csv:3", "grad_Gx"});
}

TEST_F(BadData, CsvWrongTypeInLabelColumn) {
  expect_all_refuse(csv_text("label.csv", "a.png,0,0,5,5,1,2,3,4,5,6,7,False,yes,False\n"),
                    {"label.csv:2", "is_field_marking"});
}

TEST_F(BadData, CsvNaN) {
  expect_all_refuse(csv_text("nan.csv", kGoodRow + kGoodRow + "a.png,0,0,5,5,1,2,3,4,NaN,6,7,False,True,False\n"),
                    {"nan.csv:4", "grad_Gy"});
}

TEST_F(BadData, CsvInfinity) {
  expect_all_refuse(csv_text("inf.csv", "a.png,0,0,5,5,1,2,3,4,5,6,inf,False,True,False\n"),
                    {"inf.csv:2", "segment_length"});
}

TEST_F(BadData, CsvNumberOverflow) {
  expect_all_refuse(csv_text("big.csv", "a.png,0,0,5,1e999,1,2,3,4,5,6,7,False,True,False\n"), {"big.csv:2", "y1"});
}

TEST_F(BadData, CsvDuplicateRowsAreKeptAndCountTwice) {
  // Decision (docs/bad_input.md): a repeated row is a second labelled sample, as in the
  // authors' files, so eval counts it twice. Nothing is merged silently.
  const fs::path once = csv_text("once.csv", kGoodRow);
  const fs::path twice = csv_text("twice.csv", kGoodRow + kGoodRow);
  const fs::path t = thresholds("t.json");
  const auto a = run({"eval", once.string(), "--thresholds", t.string(), "--json", path("a.json").string()});
  const auto b = run({"eval", twice.string(), "--thresholds", t.string(), "--json", path("b.json").string()});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const json ja = json::parse(read_text(path("a.json"))).at("total");
  const json jb = json::parse(read_text(path("b.json"))).at("total");
  const auto total = [](const json& c) {
    long n = 0;
    for (const auto& [cls, counts] : c.items())
      for (const char* k : {"tp", "fn"})
        if (counts.contains(k)) n += counts.at(k).get<long>();
    return n;
  };
  EXPECT_GT(total(ja), 0) << ja;
  EXPECT_EQ(total(jb), 2 * total(ja)) << jb;
}

TEST_F(BadData, CsvWithoutLabelledRows) {
  // Header only: train and sweep have nothing to learn from and say which file; eval reports
  // zero counts (exit 0).
  const fs::path data = bytes("header_only.csv", kCsvHeader);
  const auto t = run({"train", data.string(), "--quiet", "-o", path("out.json").string()});
  EXPECT_CLI_FAILS(t, 2, "no labelled segments");
  const auto s = run({"sweep", data.string(), "--quiet", "--seeds", "1"});
  EXPECT_CLI_FAILS(s, 2, "header_only.csv: holds no labelled segments");
  const auto e = run({"eval", data.string(), "--thresholds", thresholds("t.json").string()});
  EXPECT_EQ(e.exit_code, 0) << e.err;
  EXPECT_FALSE(fs::exists(path("out.json")));
}

// ---- project files: train, eval, sweep; autolabel never overwrites one it cannot read ----------

TEST_F(BadData, ProjectMalformedJson) {
  expect_all_refuse(bytes("p.json", "{\"format\": \"fieldlines-project\", \"images\": [}"), {"p.json", "malformed JSON"});
}

TEST_F(BadData, ProjectNewerVersion) {
  json j = json::parse(read_text(project("p.json")));
  j["version"] = 99;
  bytes("p.json", j.dump());
  expect_all_refuse(path("p.json"), {"p.json", "newer"});
}

TEST_F(BadData, ProjectOutOfRangeDetectorValue) {
  json j = json::parse(read_text(project("p.json")));
  j["detector"]["scan_interval"] = -3;
  bytes("p.json", j.dump());
  expect_all_refuse(path("p.json"), {"p.json", "scan_interval"});
}

TEST_F(BadData, ProjectSegmentValueBeyondFloat) {
  // Valid JSON, but 1e300 is infinite as the float a segment holds.
  json j = json::parse(read_text(project("p.json")));
  j["images"][0]["segments"][0][9] = 1e300;
  bytes("p.json", j.dump());
  expect_all_refuse(path("p.json"), {"p.json: images[0].segments[0]: 'gy_g' must be finite"});
}

TEST_F(BadData, ProjectWrongTypeInSegment) {
  json j = json::parse(read_text(project("p.json")));
  j["images"][0]["segments"][0][0] = "left";
  bytes("p.json", j.dump());
  expect_all_refuse(path("p.json"), {"p.json"});
}

TEST_F(BadData, AutolabelRefusesToOverwriteAnUnreadableProject) {
  const fs::path set = synth_set("set");
  const std::string precious = "{\"format\": \"fieldlines-project\", \"version\": 1, \"images\": [ hand edited";
  const fs::path p = bytes("p.json", precious);
  const auto r = run({"autolabel", set.string(), "--quiet", "-o", p.string()});
  EXPECT_CLI_FAILS(r, 2, "refusing to overwrite", "p.json");
  EXPECT_EQ(read_text(p), precious);
}

// ---- thresholds files: detect, eval, autolabel --thresholds ----------------------------------

class BadThresholds : public BadInputTest {
 protected:
  // detect, eval and autolabel given `file` as --thresholds: exit 2 naming it and the problem.
  void expect_all_refuse(const fs::path& file, const std::vector<std::string>& parts) {
    const std::vector<std::vector<std::string>> commands = {
        {"detect", "--thresholds", file.string(), "--json", path("out.json").string(), field_image("f.png").string()},
        {"eval", csv("d.csv").string(), "--thresholds", file.string(), "--json", path("out.json").string()},
        {"autolabel", synth_set("set_" + std::to_string(counter_++)).string(), "--thresholds", file.string(), "-o",
         path("out.json").string()}};
    for (const auto& c : commands) {
      SCOPED_TRACE(c.front());
      const auto r = run(c);
      EXPECT_EQ(r.exit_code, 2) << r.err;
      for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << "missing '" << p << "' in:\n" << r.err;
      EXPECT_FALSE(fs::exists(path("out.json")));
    }
  }
  json good() const { return json::parse(read_text(thresholds("good.json"))); }
  int counter_ = 0;
};

TEST_F(BadThresholds, Missing) { expect_all_refuse(path("none.json"), {"none.json"}); }

TEST_F(BadThresholds, Empty) { expect_all_refuse(bytes("empty.json", ""), {"empty.json"}); }

TEST_F(BadThresholds, Malformed) { expect_all_refuse(bytes("m.json", "{\"format\": "), {"m.json", "malformed JSON"}); }

TEST_F(BadThresholds, NotAThresholdsFile) {
  expect_all_refuse(csv("data.csv"), {"data.csv", "malformed JSON"});
}

TEST_F(BadThresholds, NewerVersion) {
  json j = good();
  j["version"] = 2;
  expect_all_refuse(bytes("v.json", j.dump()), {"v.json", "newer"});
}

TEST_F(BadThresholds, OutOfRangeAngle) {
  json j = good();
  j["classes"]["marking"]["max_angle_deg"] = 720;
  expect_all_refuse(bytes("a.json", j.dump()), {"a.json", "classes.marking.max_angle_deg"});
}

TEST_F(BadThresholds, OutOfRangeDetectorParameter) {
  json j = good();
  j["detector"]["gradient_threshold"] = -1;
  expect_all_refuse(bytes("g.json", j.dump()), {"g.json", "gradient_threshold"});
}

TEST_F(BadThresholds, NumberOverflow) {
  std::string text = good().dump();
  const std::string key = "\"min_length\":";
  text.insert(text.find(key) + key.size(), "1e999");
  text.erase(text.find("1e999") + 5, text.find_first_of(",}", text.find("1e999")) - text.find("1e999") - 5);
  expect_all_refuse(bytes("o.json", text), {"o.json"});
}

TEST_F(BadThresholds, NaNIsNotJson) {
  std::string text = good().dump();
  const std::string key = "\"min_projection\":";
  const auto at = text.find(key) + key.size();
  text.replace(at, text.find_first_of(",}", at) - at, "NaN");
  expect_all_refuse(bytes("n.json", text), {"n.json", "malformed JSON"});
}

}  // namespace
