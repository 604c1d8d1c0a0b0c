// `fieldlines bench` end to end: the JSON schema, all seven rows in both orders, the worse-order
// ratios the targets are checked on, bad inputs. Speed itself is not asserted here (that is what
// the benchmark is for); only that the numbers are sane and consistent with each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "bench/peers/order_rounds.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "cli_test_support.hpp"
#include "painted_field.hpp"

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
  for (const char* word : {"edlines", "fld", "lsd", "gradients", "floor", "--rounds", "--repeat", "--seed", "--clock",
                           "--json", "--scale", "--detector-threads", "--thresholds", "block", "interleaved", "worse", "JSON:",
                           "\"ours_over_this\"", "\"targets\"", "examples:"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// A ratio summary: both orders, the worse one is their maximum and names its order, the spread
// over rounds brackets it.
void expect_ratio_summary(const json& r) {
  const double block = r.at("block"), interleaved = r.at("interleaved"), worse = r.at("worse");
  const double lo = r.at("min"), hi = r.at("max");
  EXPECT_TRUE(std::isfinite(block) && block > 0 && std::isfinite(interleaved) && interleaved > 0) << r;
  EXPECT_DOUBLE_EQ(worse, std::max(block, interleaved)) << r;
  EXPECT_EQ(r.at("worse_order"), block >= interleaved ? "block" : "interleaved") << r;
  EXPECT_LE(lo, worse) << r;
  EXPECT_GE(hi, worse) << r;
}

TEST_F(CliBench, JsonListsAllSevenRowsInBothOrders) {
  const fs::path a = write_image("a.png", synthetic_field(640, 480));
  const fs::path b = write_image("b.png", synthetic_field(640, 480, 11));
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--rounds", "3", "--repeat", "2", "--seed", "9", "--json", out.string(), a.string(),
                            b.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_text(out));
  EXPECT_EQ(j.at("images"), 2);
  EXPECT_EQ(j.at("rounds"), 3);
  EXPECT_EQ(j.at("passes_per_round"), 2);
  EXPECT_EQ(j.at("seed"), 9);
  EXPECT_EQ(j.at("clock"), "thread-cpu");
  std::vector<std::string> names;
  std::map<std::string, json> rows;
  for (const auto& d : j.at("detectors")) {
    names.push_back(d.at("name"));
    rows[d.at("name")] = d;
    // Pooled over both orders, and per order.
    for (const json& t : {d, d.at("block"), d.at("interleaved")}) {
      const double median = t.at("median_ms"), p90 = t.at("p90_ms");
      EXPECT_TRUE(std::isfinite(median) && median > 0) << d;
      EXPECT_GE(p90, median) << d;
    }
    for (const char* statistic : {"median_ms", "mean_ms"}) {
      const double pooled = d.at(statistic);
      const double block = d.at("block").at(statistic), interleaved = d.at("interleaved").at(statistic);
      EXPECT_TRUE(std::isfinite(pooled) && pooled > 0) << statistic << " " << d;
      EXPECT_GE(pooled, std::min(block, interleaved) - 1e-12) << statistic << " " << d;
      EXPECT_LE(pooled, std::max(block, interleaved) + 1e-12) << statistic << " " << d;
    }
    expect_ratio_summary(d.at("ours_over_this"));
    const double segments = d.at("segments_per_image");
    EXPECT_GE(segments, 0) << d;
    // The floor and our gradient stage find no segments; every real detector finds the lines.
    if (d["name"] == "floor" || d["name"] == "gradients") EXPECT_EQ(segments, 0) << d;
    else EXPECT_GT(segments, 0) << d;
  }
  EXPECT_EQ(names,
            (std::vector<std::string>{"fieldlines", "fieldlines+light", "fieldlines+stripes", "fieldlines+coarse",
                                      "fieldlines+thin", "fieldlines+scales", "fieldlines+junctions", "fieldlines+features", "fieldlines+ground", "edlines", "fld", "lsd", "gradients", "floor"}));
  // The camera changes what lies on the ground, not the segments.
  EXPECT_EQ(rows["fieldlines+ground"]["segments_per_image"], rows["fieldlines+features"]["segments_per_image"]);
  // The light adaptation finds the same segments (the field's colour is the reference's here).
  EXPECT_EQ(rows["fieldlines+light"]["segments_per_image"], rows["fieldlines"]["segments_per_image"]);
  // Ours against ours is 1 in every order and round.
  for (const char* k : {"block", "interleaved", "worse", "min", "max"})
    EXPECT_DOUBLE_EQ(rows["fieldlines"]["ours_over_this"][k].get<double>(), 1.0) << k;

  // The targets are checked on the worse order's ratio of their row.
  for (const auto& [peer, limit] : {std::pair<std::string, double>{"edlines", 0.4}, {"floor", 1.5}}) {
    const json& t = j.at("targets").at(peer);
    const json& row = rows[peer]["ours_over_this"];
    EXPECT_DOUBLE_EQ(t.at("ratio").get<double>(), row.at("worse").get<double>()) << peer;
    EXPECT_EQ(t.at("order"), row.at("worse_order")) << peer;
    EXPECT_DOUBLE_EQ(t.at("min").get<double>(), row.at("min").get<double>()) << peer;
    EXPECT_DOUBLE_EQ(t.at("max").get<double>(), row.at("max").get<double>()) << peer;
    EXPECT_DOUBLE_EQ(t.at("limit").get<double>(), limit) << peer;
    EXPECT_EQ(t.at("met").get<bool>(), t.at("ratio").get<double>() <= limit) << peer;
  }
  expect_ratio_summary(j.at("gradients_over_floor"));
  // Junctions, circle and boundary add features, not segments: the stripes' segments.
  EXPECT_EQ(rows["fieldlines+features"]["segments_per_image"], rows["fieldlines+stripes"]["segments_per_image"]);
  EXPECT_EQ(rows["fieldlines+junctions"]["segments_per_image"], rows["fieldlines+stripes"]["segments_per_image"]);
  expect_ratio_summary(j.at("junctions_over_plain"));
  expect_ratio_summary(j.at("features_over_plain"));
  expect_ratio_summary(j.at("ground_over_features"));
  expect_ratio_summary(j.at("coarse_over_plain"));
  expect_ratio_summary(j.at("thin_over_plain"));
  expect_ratio_summary(j.at("scales_over_plain"));
  // The coarse and thin-line passes add segments where the full scale has none, and never take
  // one away.
  for (const char* pass : {"fieldlines+coarse", "fieldlines+thin"})
    EXPECT_GE(rows[pass]["segments_per_image"], rows["fieldlines"]["segments_per_image"]) << pass;
  EXPECT_GE(rows["fieldlines+scales"]["segments_per_image"], rows["fieldlines+coarse"]["segments_per_image"]);

  // The table shows both orders, the worse ratio with its spread and the target checks on it.
  EXPECT_NE(r.out.find("2 images x 3 rounds x 2 passes in each order (block, interleaved; seed 9)"), std::string::npos)
      << r.out;
  for (const char* word : {"block ms", "interl. ms", "ours/this", "worse [min-max, order]", "thread-cpu time",
                           "targets, checked on the worse order"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word << "\n" << r.out;
  const json& e = j["targets"]["edlines"];
  const std::string edlines_line =
      cv::format("fieldlines/edlines = %.2f [%.2f-%.2f, %s] (<= 0.40: %s)", e["ratio"].get<double>(), e["min"].get<double>(),
                 e["max"].get<double>(), e["order"].get<std::string>().c_str(), e["met"].get<bool>() ? "met" : "NOT met");
  EXPECT_NE(r.out.find(edlines_line), std::string::npos) << edlines_line << "\n" << r.out;
  EXPECT_NE(r.out.find("fieldlines/floor = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gradients/floor = "), std::string::npos) << r.out;
}

TEST_F(CliBench, OneRoundHasNoSpread) {
  const fs::path a = write_image("a.png", synthetic_field(320, 240));
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--rounds", "1", "--quiet", "--json", out.string(), a.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Named: a range-for over a temporary's member would read the freed document.
  const json report = json::parse(read_text(out));
  for (const auto& d : report.at("detectors")) {
    const json& ratio = d.at("ours_over_this");
    EXPECT_DOUBLE_EQ(ratio.at("min").get<double>(), ratio.at("worse").get<double>()) << d;
    EXPECT_DOUBLE_EQ(ratio.at("max").get<double>(), ratio.at("worse").get<double>()) << d;
  }
}

TEST_F(CliBench, BadImagesAreSkippedAndReported) {
  const fs::path good = write_image("good.png", synthetic_field(320, 240));
  const fs::path bad = dir_ / "bad.png";
  std::ofstream(bad, std::ios::binary) << "not an image";
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--rounds", "1", "--json", out.string(), good.string(), bad.string()}, dir_);
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
  for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
           {"--rounds", "0"}, {"--rounds", "many"}, {"--seed", "-1"}, {"--clock", "cycles"}}) {
    const CliRun bad_value = run_cli({"bench", "--quiet", option, value, good.string()}, dir_);
    EXPECT_EQ(bad_value.exit_code, 2) << option << " " << value;
    EXPECT_NE(bad_value.err.find(option), std::string::npos) << option << " " << value << ": " << bad_value.err;
  }
}

TEST_F(CliBench, ChecksTheFloorTargetItIsGiven) {
  const fs::path a = write_image("a.png", synthetic_field(320, 240));
  // No detector is 100x the floor, none is a tenth of it: the check must say met, then NOT met.
  const CliRun loose = run_cli({"bench", "--rounds", "1", "--quiet", "--floor-target", "100", a.string()}, dir_);
  ASSERT_EQ(loose.exit_code, 0) << loose.err;
  EXPECT_NE(loose.out.find("(<= 100.00: met)"), std::string::npos) << loose.out;
  const CliRun tight = run_cli({"bench", "--rounds", "1", "--quiet", "--floor-target", "0.1", a.string()}, dir_);
  ASSERT_EQ(tight.exit_code, 0) << tight.err;
  EXPECT_NE(tight.out.find("(<= 0.10: NOT met)"), std::string::npos) << tight.out;
}

TEST_F(CliBench, ScalesEveryImageAndSaysSo) {
  // Two sizes in, one size timed: the table and the JSON name the scaled size.
  const fs::path a = write_image("a.png", synthetic_field(320, 240));
  const fs::path b = write_image("b.png", synthetic_field(640, 480, 5));
  const fs::path out = dir_ / "bench.json";
  const CliRun r = run_cli({"bench", "--rounds", "1", "--quiet", "--scale", "400x300", "--json", out.string(),
                            a.string(), b.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 images scaled to 400x300 x 1 round x 1 pass in each order"), std::string::npos) << r.out;
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
  const CliRun r = run_cli({"bench", "--rounds", "1", "--quiet", "--detector-threads", "2", "--json", out.string(),
                            a.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fieldlines and gradients: 2 detector threads"), std::string::npos) << r.out;
  const json j = json::parse(read_text(out));
  EXPECT_EQ(j.at("detector_threads"), 2);
  EXPECT_FALSE(j.contains("scale"));
  // The bands run on other threads: the calling thread's CPU time would miss them.
  EXPECT_EQ(j.at("clock"), "wall");
  const CliRun cpu = run_cli({"bench", "--quiet", "--detector-threads", "2", "--clock", "thread-cpu", a.string()}, dir_);
  EXPECT_EQ(cpu.exit_code, 2);
  EXPECT_NE(cpu.err.find("--clock wall"), std::string::npos) << cpu.err;
  for (const char* bad : {"0", "65", "two"}) {
    const CliRun usage = run_cli({"bench", "--quiet", "--detector-threads", bad, a.string()}, dir_);
    EXPECT_EQ(usage.exit_code, 2) << bad;
    EXPECT_NE(usage.err.find("--detector-threads"), std::string::npos) << bad << ": " << usage.err;
  }
}

// With a thresholds file, our rows run its parameters: its shorter minimum length keeps a mark
// the built-in one leaves out, and the file's own thin-line pass stays out of the plain row (on a far,
// faint 2 px line under a wall, which only that pass draws along its centre).
TEST_F(CliBench, ThresholdsFileSetsOurRows) {
  cv::Mat clean(480, 640, CV_8UC3, fieldlines::test::kTurf);
  const std::vector<cv::Point> wall{{0, 0}, {639, 0}, {639, 108}, {0, 95}};  // 5 px above the line
  cv::fillConvexPoly(clean, wall, fieldlines::test::kDark);
  const cv::Scalar faint = 0.75 * fieldlines::test::kTurf + 0.25 * cv::Scalar(255, 255, 255);
  cv::line(clean, {40, 100}, {600, 112}, faint, 2, cv::LINE_AA);
  cv::line(clean, {100, 300}, {540, 330}, cv::Scalar(255, 255, 255), 6, cv::LINE_AA);
  cv::line(clean, {300, 420}, {334, 420}, cv::Scalar(255, 255, 255), 6);  // shorter than the built-in minimum
  const fs::path a = write_image("a.png", fieldlines::test::noisy(clean));
  const auto segments = [](const json& j, const std::string& name) {
    for (const json& d : j.at("detectors"))
      if (d.at("name") == name) return d.at("segments_per_image").get<double>();
    ADD_FAILURE() << "no row " << name;
    return -1.0;
  };
  const fs::path built_in = dir_ / "built-in.json";
  ASSERT_EQ(run_cli({"bench", "--rounds", "1", "--quiet", "--json", built_in.string(), a.string()}, dir_).exit_code, 0);
  fieldlines::ThresholdsFile file;
  file.detector.gaussian_kernel = 5;
  file.detector.scan_interval = 2;
  file.detector.min_line_length = 25;
  file.detector.thin_reach = 2;  // the plain row must not run it
  const fs::path th = dir_ / "dense.json";
  fieldlines::save_thresholds_file(th, file);
  const fs::path dense = dir_ / "dense-bench.json";
  const CliRun r = run_cli({"bench", "--rounds", "1", "--quiet", "--thresholds", th.string(), "--json", dense.string(),
                            a.string()},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fieldlines rows: the detector parameters and thresholds of"), std::string::npos) << r.out;
  const json jb = json::parse(read_text(built_in)), jd = json::parse(read_text(dense));
  EXPECT_FALSE(jb.contains("thresholds"));
  EXPECT_EQ(jd.at("thresholds"), th.string());
  EXPECT_GT(segments(jd, "fieldlines"), segments(jb, "fieldlines"));
  EXPECT_LT(segments(jd, "fieldlines"), segments(jd, "fieldlines+thin"));
  const CliRun missing = run_cli({"bench", "--quiet", "--thresholds", (dir_ / "none.json").string(), a.string()}, dir_);
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
}

// The rounds behind `fieldlines bench`, with stand-in detectors that log their calls.
TEST(BenchRounds, BlockRunsEachDetectorBackToBackAndInterleavedVisitsEveryImage) {
  std::vector<std::pair<std::size_t, int>> log;  // (detector, image id) per call
  std::vector<fieldlines::peers::TimedDetector> detectors;
  const std::vector<std::string> names{"d0", "d1", "d2"};
  for (std::size_t d = 0; d < 3; ++d)
    detectors.push_back({names[d], "stand-in", [&log, d](const cv::Mat& image) {
                           log.emplace_back(d, image.at<unsigned char>(0, 0));
                           return d;  // "segments"
                         }});
  std::vector<cv::Mat> images;
  for (int i = 0; i < 4; ++i) images.push_back(cv::Mat(2, 2, CV_8UC1, cv::Scalar(i)));
  const fieldlines::peers::RoundsParams params{3, 2, 7, fieldlines::peers::Clock::Wall};
  std::size_t ticks = 0;
  const auto times = fieldlines::peers::time_in_both_orders(detectors, images, params, [&ticks] { ++ticks; });

  EXPECT_EQ(ticks, fieldlines::peers::calls_expected(3, 4, params));
  EXPECT_EQ(log.size(), ticks);
  ASSERT_EQ(times.size(), 3u);
  for (std::size_t d = 0; d < 3; ++d) {
    EXPECT_EQ(times[d].name, names[d]);
    EXPECT_DOUBLE_EQ(times[d].segments, 4.0 * static_cast<double>(d));  // the warm-up pass counts them
    for (const auto& by_round : times[d].ms) {
      ASSERT_EQ(by_round.size(), 3u);
      for (const auto& calls : by_round) EXPECT_EQ(calls.size(), 8u);  // 2 passes x 4 images
    }
  }
  // After the warm-up (12 calls), each round holds a block of 3 x (1 untimed + 8) calls, each
  // detector's contiguous, and an interleaved part of 8 groups of 3: one image, every detector.
  std::size_t at = 12, blocks = 0, interleaved = 0;
  const auto is_block = [&](std::size_t from) {
    for (std::size_t k = 1; k < 9; ++k)
      if (log[from + k].first != log[from].first) return false;
    return true;
  };
  for (int round = 0; round < 3; ++round) {
    for (int part = 0; part < 2; ++part) {
      if (is_block(at)) {
        std::set<std::size_t> seen;
        for (int d = 0; d < 3; ++d, at += 9) {
          EXPECT_TRUE(is_block(at)) << "round " << round;
          EXPECT_EQ(log[at].second, 0) << "the untimed call is on the first image";
          seen.insert(log[at].first);
        }
        EXPECT_EQ(seen.size(), 3u);
        ++blocks;
      } else {
        for (int group = 0; group < 8; ++group, at += 3) {
          std::set<std::size_t> seen;
          for (std::size_t k = 0; k < 3; ++k) {
            seen.insert(log[at + k].first);
            EXPECT_EQ(log[at + k].second, group % 4) << "round " << round;
          }
          EXPECT_EQ(seen.size(), 3u) << "round " << round;
        }
        ++interleaved;
      }
    }
  }
  EXPECT_EQ(at, log.size());
  EXPECT_EQ(blocks, 3u);
  EXPECT_EQ(interleaved, 3u);
}

TEST(BenchRounds, TheWorseOrderIsTheLargerRatioWithItsSpreadOverRounds) {
  using fieldlines::peers::Order;
  fieldlines::peers::DetectorTimes ours, peer;
  // Per round, summed times: ours/peer is 0.5, 0.6, 0.7 in block order and 0.2, 0.3, 0.4
  // interleaved. The medians of the calls would give 1.0 in the first block round (two cheap
  // frames beside a dear one: 1/1) and 0.05 in the last interleaved one (2/40).
  ours.ms[0] = {{1, 1, 8}, {6}, {7}};
  peer.ms[0] = {{1, 1, 18}, {10}, {10}};
  ours.ms[1] = {{2}, {3}, {2, 2, 36}};
  peer.ms[1] = {{10}, {10}, {20, 40, 40}};
  const auto r = fieldlines::peers::ratio_in_both_orders(ours, peer);
  EXPECT_DOUBLE_EQ(r.by_order[0], 0.6);
  EXPECT_DOUBLE_EQ(r.by_order[1], 0.3);
  EXPECT_EQ(r.worse_order, Order::Block);
  EXPECT_DOUBLE_EQ(r.worse, 0.6);
  EXPECT_DOUBLE_EQ(r.min, 0.5);
  EXPECT_DOUBLE_EQ(r.max, 0.7);
  // Swapped orders: the interleaved one is now worse, and its own spread is reported.
  std::swap(ours.ms[0], ours.ms[1]);
  std::swap(peer.ms[0], peer.ms[1]);
  const auto s = fieldlines::peers::ratio_in_both_orders(ours, peer);
  EXPECT_EQ(s.worse_order, Order::Interleaved);
  EXPECT_DOUBLE_EQ(s.worse, 0.6);
  EXPECT_DOUBLE_EQ(s.min, 0.5);
  EXPECT_DOUBLE_EQ(s.max, 0.7);
}
