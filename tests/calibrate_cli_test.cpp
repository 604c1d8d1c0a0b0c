// `fieldlines calibrate` end to end through the built CLI: every kind of PATH, labels never
// read, the same input giving the same bytes, and bad input refused with exit 2 and no file.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/thresholds_file.hpp"

namespace fl = fieldlines;
namespace fs = std::filesystem;
using fl::test::read_text;
using fl::test::run_cli;

namespace {

class Calibrate : public fl::test::TempDirTest {
 protected:
  // The authors' D2 rows with the labels replaced by `relabel` (or dropped when it is empty).
  fs::path d2_copy(const std::string& name, bool shuffle_labels, bool drop_label_columns) {
    const std::vector<fl::ReferenceRow> rows =
        fl::read_reference_csv(fl::test::shared_dir() / "data/elsed-ssl/annotations/D2_ssl_mixed_light.csv");
    std::vector<fl::ReferenceRow> out = rows;
    if (shuffle_labels) {
      std::mt19937 rng(5);
      std::vector<fl::Label> labels;
      for (const auto& r : rows) labels.push_back(r.segment.label);
      std::shuffle(labels.begin(), labels.end(), rng);
      for (std::size_t i = 0; i < out.size(); ++i) out[i].segment.label = labels[i];
    }
    const fs::path path = dir_ / name;
    fl::write_reference_csv(path, out);
    if (drop_label_columns) {
      // Cut the three label columns off every line.
      std::ifstream in(path);
      std::string text, line;
      while (std::getline(in, line)) {
        for (int k = 0; k < 3; ++k) line.erase(line.rfind(','));
        text += line + "\n";
      }
      in.close();
      std::ofstream(path, std::ios::trunc) << text;
    }
    return path;
  }
  static nlohmann::json classes(const fs::path& thresholds) {
    return nlohmann::json::parse(read_text(thresholds))["classes"];
  }
};

TEST_F(Calibrate, LabelsAreNeverReadAndTheSameInputGivesTheSameBytes) {
  FIELDLINES_REQUIRE_SHARED("data/elsed-ssl/annotations/D2_ssl_mixed_light.csv", d2);
  const fs::path labelled = d2_copy("labelled.csv", false, false);
  const fs::path shuffled = d2_copy("shuffled.csv", true, false);
  const fs::path bare = d2_copy("bare.csv", false, true);
  ASSERT_EQ(read_text(bare).substr(0, read_text(bare).find('\n')).find("is_field"), std::string::npos);
  for (const auto& [in, out] : {std::pair{labelled, "a.json"}, {labelled, "a2.json"}, {shuffled, "b.json"}, {bare, "c.json"}}) {
    const auto r = run_cli({"calibrate", in.string(), "-o", (dir_ / out).string(), "--quiet"}, dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_EQ(read_text(dir_ / "a.json"), read_text(dir_ / "a2.json"));
  EXPECT_EQ(classes(dir_ / "a.json"), classes(dir_ / "b.json"));
  EXPECT_EQ(classes(dir_ / "a.json"), classes(dir_ / "c.json"));
  // An ordinary thresholds file the robot loads, with its provenance.
  const fl::ThresholdsFile file = fl::load_thresholds_file(dir_ / "a.json");
  EXPECT_EQ(file.provenance["method"], "label-free");
  EXPECT_EQ(file.provenance["counts"]["segments"], 2684);
  // Segments from a file were detected already: the detector parameters stay those given.
  EXPECT_EQ(file.detector, fl::DetectorParams{});
  EXPECT_FALSE(file.provenance["detector"]["calibrated"].get<bool>());
  EXPECT_TRUE(file.provenance["fit"]["marking"]["fitted"].get<bool>());
  EXPECT_GT(file.thresholds.marking.thresholds.max_angle_deg, 30.f);
  EXPECT_LT(file.thresholds.marking.thresholds.max_angle_deg, 35.f);
  // And `eval` scores it against the human labels.
  const auto e = run_cli({"eval", labelled.string(), "--thresholds", (dir_ / "a.json").string(), "--json",
                          (dir_ / "eval.json").string()}, dir_);
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const auto total = nlohmann::json::parse(read_text(dir_ / "eval.json"))["total"];
  EXPECT_GE(total["marking"]["precision"].get<double>(), 0.95);
  EXPECT_GE(total["marking"]["recall"].get<double>(), 0.90);
}

TEST_F(Calibrate, ImageFoldersAreDetectedThenFittedWithAReport) {
  const fs::path set = dir_ / "set";
  const auto s = run_cli({"synth", "--scene", "ssl", "--n", "16", "--seed", "4", "-o", set.string(), "--quiet"}, dir_);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const fs::path out = dir_ / "robot.json", report = dir_ / "fit.json";
  const auto r = run_cli({"calibrate", set.string(), "-o", out.string(), "--json", report.string()}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("marking"), std::string::npos) << r.out;
  // The detector the frames chose, and why the coarse pass is off on a plain synthetic field.
  EXPECT_NE(r.out.find("detector: scan interval 2, min length 25, stripes up to "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; one scale (a coarse pass would add"), std::string::npos) << r.out;
  const fl::ThresholdsFile file = fl::load_thresholds_file(out);
  // The widest stripe from the frames' own lines (stripe_width.hpp), recorded where it came from.
  EXPECT_LT(file.detector.stripe_max_width, fl::DetectorParams{}.stripe_max_width);
  EXPECT_EQ(file.provenance["detector"]["stripe_max_width"].get<double>(), file.detector.stripe_max_width);
  EXPECT_EQ(file.provenance["counts"]["images"], 16);
  EXPECT_EQ(file.detector.coarse_scale, 1);
  EXPECT_LT(file.provenance["detector"]["coarse_gain"].get<double>(), 0.2);
  // From pictures of a field: light adaptation and the field boundary gate on for the robot,
  // and both off with --no-light-adaptation for the light alone.
  EXPECT_TRUE(file.thresholds.light.enabled);
  EXPECT_GT(file.thresholds.light.reference_field[1], file.thresholds.light.reference_field[0]);
  EXPECT_TRUE(file.thresholds.field_boundary_gate);
  const fs::path plain = dir_ / "plain.json";
  ASSERT_EQ(run_cli({"calibrate", set.string(), "-o", plain.string(), "--no-light-adaptation", "--quiet"}, dir_).exit_code, 0);
  EXPECT_FALSE(fl::load_thresholds_file(plain).thresholds.light.enabled);
  EXPECT_TRUE(fl::load_thresholds_file(plain).thresholds.field_boundary_gate);
  const auto fit = nlohmann::json::parse(read_text(report));
  EXPECT_TRUE(fit["fit"]["marking"]["fitted"].get<bool>()) << fit.dump(2);
  EXPECT_GE(fit["fit_ms"].get<double>(), 0.0);
  EXPECT_EQ(fit["thresholds"], classes(out));
}

TEST_F(Calibrate, PicturesChooseTheDetectorAndKeepDetectorKeepsTheGivenOne) {
  const fs::path set = dir_ / "set";
  ASSERT_EQ(run_cli({"synth", "--scene", "kid", "--n", "12", "--seed", "3", "-o", set.string(), "--quiet"}, dir_).exit_code, 0);
  const fs::path chosen = dir_ / "chosen.json", kept = dir_ / "kept.json", given = dir_ / "given.json";
  const auto r = run_cli({"calibrate", set.string(), "-o", chosen.string(), "--quiet"}, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The file still loads, with the venue's detector: the finer anchor grid and the stripes on.
  const fl::ThresholdsFile file = fl::load_thresholds_file(chosen);
  EXPECT_EQ(file.detector.scan_interval, 2);
  EXPECT_EQ(file.detector.gaussian_kernel, 5);
  EXPECT_EQ(file.detector.min_line_length, 25);
  EXPECT_TRUE(file.detector.stripes);
  EXPECT_TRUE(file.detector.stripe_turf_colours);
  EXPECT_GE(file.detector.gradient_threshold, 8);
  EXPECT_LE(file.detector.gradient_threshold, fl::DetectorParams{}.gradient_threshold);
  EXPECT_TRUE(file.provenance["detector"]["calibrated"].get<bool>());
  EXPECT_EQ(file.provenance["detector"]["frames_with_field"], 12);
  // --keep-detector: the parameters of --thresholds (here the built-in ones, one changed).
  fl::ThresholdsFile start;
  start.detector.min_line_length = 33;
  fl::save_thresholds_file(given, start);
  ASSERT_EQ(run_cli({"calibrate", set.string(), "-o", kept.string(), "--thresholds", given.string(), "--keep-detector",
                     "--quiet"}, dir_).exit_code, 0);
  const fl::ThresholdsFile k = fl::load_thresholds_file(kept);
  EXPECT_EQ(k.detector, start.detector);
  EXPECT_FALSE(k.provenance["detector"]["calibrated"].get<bool>());
  EXPECT_TRUE(k.provenance["fit"]["marking"]["fitted"].get<bool>());
  // And the robot's command reads both.
  for (const fs::path& t : {chosen, kept})
    EXPECT_EQ(run_cli({"detect", set.string(), "--thresholds", t.string(), "--quiet"}, dir_).exit_code, 0);
}

TEST_F(Calibrate, BadInputIsAMessageExit2AndNoFile) {
  const fs::path out = dir_ / "robot.json";
  const auto refused = [&](const std::vector<std::string>& args, const std::string& message) {
    std::vector<std::string> all{"calibrate"};
    all.insert(all.end(), args.begin(), args.end());
    const auto r = run_cli(all, dir_);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << "expected '" << message << "' in: " << r.err;
    EXPECT_FALSE(fs::exists(out));
  };
  // A folder of pictures without a field: grey, black and noise.
  cv::Mat noise(240, 320, CV_8UC3);
  cv::randu(noise, 0, 255);
  for (int i = 0; i < 4; ++i) {
    write_image("nofield/grey" + std::to_string(i) + ".png", cv::Mat(240, 320, CV_8UC3, cv::Scalar(128, 128, 128)));
    write_image("nofield/black" + std::to_string(i) + ".png", cv::Mat(240, 320, CV_8UC3, cv::Scalar(0, 0, 0)));
    cv::randu(noise, 0, 255);
    write_image("nofield/noise" + std::to_string(i) + ".png", noise);
  }
  refused({(dir_ / "nofield").string(), "-o", out.string()}, "cannot calibrate the field markings");
  // The refusal says what to do, and --json still gets the report with the reason.
  const fs::path report = dir_ / "fit.json";
  refused({(dir_ / "nofield").string(), "-o", out.string(), "--json", report.string()}, "label a few segments");
  ASSERT_TRUE(fs::exists(report));
  const nlohmann::json fit = nlohmann::json::parse(read_text(report));
  EXPECT_NE(fit["refused"].get<std::string>().find("too few segments (0"), std::string::npos) << fit.dump(2);
  EXPECT_FALSE(fit["fit"]["marking"]["fitted"].get<bool>());
  EXPECT_FALSE(fit.contains("thresholds_file"));
  // A CSV with 5 rows.
  std::string csv = "img_path,x0,y0,x1,y1,grad_Bx,grad_Gx,grad_Rx,grad_By,grad_Gy,grad_Ry,segment_length\n";
  for (int i = 0; i < 5; ++i) csv += "a.png,0,0,100," + std::to_string(i) + ",80,70,90,-30,-27,-35,120\n";
  const fs::path five = write_bytes("five.csv", csv);
  refused({five.string(), "-o", out.string()}, "too few segments (5");
  // Unwritable outputs: a missing folder, a folder, the input itself.
  refused({five.string(), "-o", (dir_ / "missing/robot.json").string()}, "missing/robot.json");
  refused({five.string(), "-o", dir_.string()}, dir_.string());
  const auto r = run_cli({"calibrate", five.string(), "-o", five.string()}, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_text(five), csv) << "the input must never be overwritten";
  // No PATH, no -o, a malformed CSV.
  refused({"-o", out.string()}, "PATH");
  refused({five.string()}, "-o");
  const fs::path bad = write_bytes("bad.csv", csv + "a.png,0,0,1,nan,1,1,1,1,1,1,1\n");
  refused({bad.string(), "-o", out.string()}, "bad.csv");
}

}  // namespace
