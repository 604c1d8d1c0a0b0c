// `fieldlines bench` end to end: the JSON schema, all six rows, bad inputs. Speed itself is
// not asserted here (that is what the benchmark is for); only that the numbers are sane.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"

namespace fs = std::filesystem;
using fieldlines::test::CliRun;
using fieldlines::test::read_text;
using fieldlines::test::run_cli;
using fieldlines::test::synthetic_field;
using nlohmann::json;

namespace {

class CliBench : public fieldlines::test::TempDirTest {};

}  // namespace

TEST_F(CliBench, HelpNamesTheDetectorsAndExamples) {
  const CliRun r = run_cli({"bench", "--help"}, dir_);
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"edlines", "fld", "lsd", "gradients", "floor", "--repeat", "--json", "--scale", "--detector-threads",
                           "examples:"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST_F(CliBench, JsonListsAllSixRowsWithSaneNumbers) {
  const fs::path a = write_image("a.png", synthetic_field(640, 480));
  const fs::path b = write_image("b.png", synthetic_field(640, 480, 11));
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--repeat", "2", "--json", out.string(), a.string(), b.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_text(out));
  EXPECT_EQ(j.at("images"), 2);
  std::vector<std::string> names;
  for (const auto& d : j.at("detectors")) {
    names.push_back(d.at("name"));
    const double median = d.at("median_ms"), p90 = d.at("p90_ms"), segments = d.at("segments_per_image");
    EXPECT_TRUE(std::isfinite(median) && median > 0) << d;
    EXPECT_GE(p90, median) << d;
    EXPECT_GE(segments, 0) << d;
    // The floor and our gradient stage find no segments; every real detector finds the lines.
    if (d["name"] == "floor" || d["name"] == "gradients") EXPECT_EQ(segments, 0) << d;
    else EXPECT_GT(segments, 0) << d;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"fieldlines", "edlines", "fld", "lsd", "gradients", "floor"}));
  // The table shows the ratios and the target check.
  EXPECT_NE(r.out.find("ours/this"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fieldlines/edlines = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fieldlines/floor = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gradients/floor = "), std::string::npos) << r.out;
}

TEST_F(CliBench, BadImagesAreSkippedAndReported) {
  const fs::path good = write_image("good.png", synthetic_field(320, 240));
  const fs::path bad = dir_ / "bad.png";
  std::ofstream(bad, std::ios::binary) << "not an image";
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--repeat", "1", "--json", out.string(), good.string(), bad.string()}, dir_);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.png: not a decodable image"), std::string::npos) << r.err;
  EXPECT_EQ(json::parse(read_text(out)).at("images"), 1);

  // Nothing loadable at all is fatal (exit 2) and says so.
  const CliRun none = run_cli({"bench", bad.string()}, dir_);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("no image could be loaded"), std::string::npos) << none.err;
  const CliRun usage = run_cli({"bench", "--repeat", "zero", good.string()}, dir_);
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_NE(usage.err.find("--repeat"), std::string::npos) << usage.err;
  const CliRun target = run_cli({"bench", "--floor-target", "nan", good.string()}, dir_);
  EXPECT_EQ(target.exit_code, 2);
  EXPECT_NE(target.err.find("--floor-target"), std::string::npos) << target.err;
}

TEST_F(CliBench, ChecksTheFloorTargetItIsGiven) {
  const fs::path a = write_image("a.png", synthetic_field(320, 240));
  // No detector is 100x the floor, none is a tenth of it: the check must say met, then NOT met.
  const CliRun loose = run_cli({"bench", "--repeat", "1", "--quiet", "--floor-target", "100", a.string()}, dir_);
  ASSERT_EQ(loose.exit_code, 0) << loose.err;
  EXPECT_NE(loose.out.find("(<= 100.00: met)"), std::string::npos) << loose.out;
  const CliRun tight = run_cli({"bench", "--repeat", "1", "--quiet", "--floor-target", "0.1", a.string()}, dir_);
  ASSERT_EQ(tight.exit_code, 0) << tight.err;
  EXPECT_NE(tight.out.find("(<= 0.10: NOT met)"), std::string::npos) << tight.out;
}

TEST_F(CliBench, ScalesEveryImageAndSaysSo) {
  // Two sizes in, one size timed: the table and the JSON name the scaled size.
  const fs::path a = write_image("a.png", synthetic_field(320, 240));
  const fs::path b = write_image("b.png", synthetic_field(640, 480, 5));
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--repeat", "1", "--quiet", "--scale", "400x300", "--json", out.string(),
                            a.string(), b.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 images scaled to 400x300 x 1 pass, single thread"), std::string::npos) << r.out;
  const json j = json::parse(read_text(out));
  EXPECT_EQ(j.at("scale").at("width"), 400);
  EXPECT_EQ(j.at("scale").at("height"), 300);
  EXPECT_EQ(j.at("detector_threads"), 1);
  for (const auto& d : j.at("detectors")) {
    if (d["name"] == "fieldlines") {
      EXPECT_GT(d.at("segments_per_image").get<double>(), 0) << d;
    }
  }

  for (const char* bad : {"640", "640x", "x480", "0x480", "640x7", "8193x100", "640x480x2", "axb", "-640x480"}) {
    const CliRun usage = run_cli({"bench", "--quiet", "--scale", bad, a.string()}, dir_);
    EXPECT_EQ(usage.exit_code, 2) << bad;
    EXPECT_NE(usage.err.find("--scale: expected WxH"), std::string::npos) << bad << ": " << usage.err;
  }
}

TEST_F(CliBench, DetectorThreadsReachOurRows) {
  const fs::path a = write_image("a.png", synthetic_field(640, 480));
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--repeat", "1", "--quiet", "--detector-threads", "2", "--json", out.string(),
                            a.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fieldlines and gradients: 2 detector threads"), std::string::npos) << r.out;
  EXPECT_EQ(json::parse(read_text(out)).at("detector_threads"), 2);
  EXPECT_FALSE(json::parse(read_text(out)).contains("scale"));
  for (const char* bad : {"0", "65", "two"}) {
    const CliRun usage = run_cli({"bench", "--quiet", "--detector-threads", bad, a.string()}, dir_);
    EXPECT_EQ(usage.exit_code, 2) << bad;
    EXPECT_NE(usage.err.find("--detector-threads"), std::string::npos) << bad << ": " << usage.err;
  }
}
