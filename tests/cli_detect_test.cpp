// `fieldlines detect` end to end: the JSON it writes matches the library, batches keep their
// order with several threads, bad files are reported and skipped, overlays are written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_test_support.hpp"
#include "painted_field.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/thresholds_file.hpp"

namespace fs = std::filesystem;
using fieldlines::test::CliRun;
using fieldlines::test::read_text;
using fieldlines::test::run_cli;
using fieldlines::test::synthetic_field;
using nlohmann::json;

namespace {

class CliDetect : public fieldlines::test::TempDirTest {
 protected:
  CliRun run(const std::vector<std::string>& args) const { return run_cli(args, dir_); }
  json read_json(const fs::path& p) const { return json::parse(read_text(p)); }
};

std::vector<std::string> image_names(const json& j) {
  std::vector<std::string> names;
  for (const auto& img : j.at("images")) names.push_back(img.at("image").get<std::string>());
  return names;
}

}  // namespace

TEST_F(CliDetect, HelpShowsOptionsAndExamples) {
  const CliRun r = run({"detect", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"--json", "--draw", "--threads", "examples:", "fieldlines detect "})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST_F(CliDetect, UsageErrorsExitWith2AndSayWhy) {
  const fs::path img = write_image("a.png", synthetic_field(160, 120));
  const CliRun none = run({"detect"});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("no PATH"), std::string::npos) << none.err;
  const CliRun unknown = run({"detect", "--bogus", img.string()});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--bogus"), std::string::npos) << unknown.err;
  const CliRun threads = run({"detect", "--threads", "0", img.string()});
  EXPECT_EQ(threads.exit_code, 2);
  EXPECT_NE(threads.err.find("--threads"), std::string::npos) << threads.err;
  // The output folder is checked before the batch runs, not after.
  const CliRun json_dir = run({"detect", "--json", (dir_ / "missing" / "out.json").string(), img.string()});
  EXPECT_EQ(json_dir.exit_code, 2);
  EXPECT_NE(json_dir.err.find("does not exist"), std::string::npos) << json_dir.err;
  EXPECT_EQ(json_dir.out.find("segments ("), std::string::npos) << "ran the batch: " << json_dir.out;
}

TEST_F(CliDetect, JsonHasTheSchemaAndTheLibrarysExactSegments) {
  const cv::Mat img = synthetic_field(640, 480);
  const fs::path path = write_image("field.png", img);
  const fs::path out = dir_ / "out.json";
  const CliRun r = run({"detect", "--json", out.string(), path.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = read_json(out);
  ASSERT_EQ(j.at("images").size(), 1u);
  EXPECT_TRUE(j.at("errors").empty());
  const json& entry = j["images"][0];
  EXPECT_EQ(entry.at("image"), "field.png");
  EXPECT_EQ(entry.at("path"), path.string());
  EXPECT_EQ(entry.at("width"), 640);
  EXPECT_EQ(entry.at("height"), 480);
  EXPECT_GE(entry.at("detect_ms").get<double>(), 0.0);

  // The same detector in this process gives the same segments, in the same order, with the
  // same R,G,B / image-down gradients (the JSON is a plain dump of fieldlines::Segment).
  fieldlines::LineDetector detector;
  const auto expected = detector.detect(img);
  const json& segments = entry.at("segments");
  ASSERT_EQ(segments.size(), expected.size());
  ASSERT_FALSE(expected.empty()) << "white lines on green must give segments";
  std::set<std::string> labels;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const json& s = segments[i];
    const auto& e = expected[i];
    EXPECT_FLOAT_EQ(s.at("x0").get<float>(), e.x0);
    EXPECT_FLOAT_EQ(s.at("y0").get<float>(), e.y0);
    EXPECT_FLOAT_EQ(s.at("x1").get<float>(), e.x1);
    EXPECT_FLOAT_EQ(s.at("y1").get<float>(), e.y1);
    EXPECT_FLOAT_EQ(s.at("saliency").get<float>(), e.saliency);
    ASSERT_EQ(s.at("grad_x").size(), 3u);
    ASSERT_EQ(s.at("grad_y").size(), 3u);
    for (int c = 0; c < 3; ++c) {
      EXPECT_FLOAT_EQ(s["grad_x"][c].get<float>(), e.grad_x[static_cast<std::size_t>(c)]);
      EXPECT_FLOAT_EQ(s["grad_y"][c].get<float>(), e.grad_y[static_cast<std::size_t>(c)]);
    }
    EXPECT_EQ(s.at("label").get<std::string>(), fieldlines::to_string(e.label));
    labels.insert(s["label"].get<std::string>());
  }
  for (const auto& l : labels) EXPECT_TRUE(l == "marking" || l == "boundary" || l == "none") << l;
  EXPECT_TRUE(labels.count("marking")) << "the painted lines are field markings";
  // The stdout summary names the image and its counts.
  EXPECT_NE(r.out.find("field.png: " + std::to_string(expected.size()) + " segments"), std::string::npos) << r.out;
}

// --stripes turns the stripes stage on (the library's markings, in soccer_vision_2d_msgs' names);
// without it, or with --no-stripes over a thresholds file that turns it on, "markings" is empty.
TEST_F(CliDetect, StripesWriteTheLibrarysMarkings) {
  const cv::Mat img = synthetic_field(640, 480);
  const fs::path path = write_image("field.png", img);
  const fs::path on = dir_ / "on.json", off = dir_ / "off.json", forced_off = dir_ / "forced_off.json";
  ASSERT_EQ(run({"detect", "--quiet", "--stripes", "--json", on.string(), path.string()}).exit_code, 0);
  ASSERT_EQ(run({"detect", "--quiet", "--json", off.string(), path.string()}).exit_code, 0);
  fieldlines::DetectorParams params;
  params.stripes = true;
  fieldlines::LineDetector detector(params);
  const auto segments = detector.detect(img);
  const auto& expected = detector.features().markings;
  ASSERT_FALSE(expected.empty());
  const json markings = read_json(on)["images"][0].at("markings");
  ASSERT_EQ(markings.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(markings[i].size(), 5u);
    EXPECT_FLOAT_EQ(markings[i].at("x0").get<float>(), expected[i].x0);
    EXPECT_FLOAT_EQ(markings[i].at("y0").get<float>(), expected[i].y0);
    EXPECT_FLOAT_EQ(markings[i].at("x1").get<float>(), expected[i].x1);
    EXPECT_FLOAT_EQ(markings[i].at("y1").get<float>(), expected[i].y1);
    EXPECT_FLOAT_EQ(markings[i].at("width").get<float>(), expected[i].width);
  }
  EXPECT_TRUE(read_json(off)["images"][0].at("markings").empty());

  fieldlines::ThresholdsFile file;
  file.detector.stripes = true;
  const fs::path thresholds = dir_ / "stripes.json";
  fieldlines::save_thresholds_file(thresholds, file);
  ASSERT_EQ(run({"detect", "--quiet", "--thresholds", thresholds.string(), "--no-stripes", "--json", forced_off.string(),
                 path.string()}).exit_code, 0);
  EXPECT_TRUE(read_json(forced_off)["images"][0].at("markings").empty());
  EXPECT_EQ(run({"detect", "--stripes", "--no-stripes", path.string()}).exit_code, 2);
}

// --features: every image's "intersections" and "ellipses" exactly as the library finds them, in
// soccer_vision_2d_msgs' names, and an overlay drawn; without it both are empty.
TEST_F(CliDetect, FeaturesWriteIntersectionsAndEllipses) {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(50, 140, 40));
  cv::line(img, cv::Point(60, 150), cv::Point(590, 170), cv::Scalar(255, 255, 255), 8);
  cv::line(img, cv::Point(320, 160), cv::Point(300, 440), cv::Scalar(255, 255, 255), 8);
  cv::ellipse(img, cv::RotatedRect(cv::Point2f(330, 330), cv::Size2f(380, 150), 0), cv::Scalar(255, 255, 255), 7);
  cv::Mat noise(img.size(), CV_8UC3);
  cv::randu(noise, 0, 8);
  img += noise;
  const fs::path path = write_image("t.png", img);
  const fs::path on = dir_ / "on.json", off = dir_ / "off.json", draw = dir_ / "draw";
  ASSERT_EQ(run({"detect", "--quiet", "--features", "--json", on.string(), "--draw", draw.string(), path.string()})
                .exit_code, 0);
  ASSERT_EQ(run({"detect", "--quiet", "--json", off.string(), path.string()}).exit_code, 0);
  EXPECT_TRUE(fs::exists(draw / "t.png"));
  fieldlines::LineDetector detector(fieldlines::with_every_feature({}));  // what --features runs
  detector.detect(img);
  const fieldlines::FieldFeatures& expected = detector.features();
  ASSERT_FALSE(expected.intersections.empty());
  ASSERT_FALSE(expected.ellipses.empty());
  const json image = read_json(on)["images"][0];
  const json& junctions = image.at("intersections");
  ASSERT_EQ(junctions.size(), expected.intersections.size());
  for (std::size_t i = 0; i < junctions.size(); ++i) {
    const fieldlines::Intersection& e = expected.intersections[i];
    const json& j = junctions[i];
    EXPECT_EQ(j.size(), 6u);
    EXPECT_FLOAT_EQ(j.at("x").get<float>(), e.x);
    EXPECT_FLOAT_EQ(j.at("y").get<float>(), e.y);
    EXPECT_EQ(j.at("type").get<std::string>(), fieldlines::to_string(e.type));
    EXPECT_EQ(j.at("num_rays").get<int>(), e.num_rays);
    ASSERT_EQ(j.at("heading_rays").size(), static_cast<std::size_t>(e.num_rays));
    for (int k = 0; k < e.num_rays; ++k)
      EXPECT_FLOAT_EQ(j["heading_rays"][static_cast<std::size_t>(k)].get<float>(), e.heading_rays[static_cast<std::size_t>(k)]);
    EXPECT_FLOAT_EQ(j.at("confidence").get<float>(), e.confidence);
  }
  const json& ellipses = image.at("ellipses");
  ASSERT_EQ(ellipses.size(), expected.ellipses.size());
  for (const char* key : {"cx", "cy", "width", "height", "angle_deg", "confidence"}) EXPECT_TRUE(ellipses[0].contains(key));
  EXPECT_FLOAT_EQ(ellipses[0].at("cx").get<float>(), expected.ellipses[0].cx);
  EXPECT_FLOAT_EQ(ellipses[0].at("angle_deg").get<float>(), expected.ellipses[0].angle_deg);
  EXPECT_TRUE(read_json(off)["images"][0].at("intersections").empty());
  EXPECT_TRUE(read_json(off)["images"][0].at("ellipses").empty());
  EXPECT_EQ(run({"detect", "--features", "--no-stripes", path.string()}).exit_code, 2);
}

// --camera: a fixed camera over the field fits the centre circle on the turf as the library
// does with the same camera; a bad camera file stops the run with a message naming the field.
TEST_F(CliDetect, CameraFileFitsTheCircleOnTheTurfAsTheLibrary) {
  const fieldlines::GroundCamera camera = fieldlines::test::ground_camera(30);
  // A circle of 0.75 m, 0.8 m ahead: the frame shows its far arc.
  cv::Mat img = fieldlines::test::painted_ground_circle(camera, {0.8, 0}, 0.75, 7);
  cv::Mat noise(img.size(), CV_8UC3);
  cv::randu(noise, 0, 8);
  img += noise;
  const fs::path path = write_image("arc.png", img), out = dir_ / "out.json";
  fs::path file = write_bytes("camera.json", fieldlines::to_json(camera).dump(2));
  const CliRun ran = run({"detect", "--features", "--camera", file.string(), "--json", out.string(), path.string()});
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  fieldlines::LineDetector detector(fieldlines::with_every_feature({}));
  detector.set_camera(fieldlines::load_camera_file(file));
  detector.detect(img);
  ASSERT_EQ(detector.features().ellipses.size(), 1u) << "the test's premise: the library finds it with the camera";
  const json ellipses = read_json(out)["images"][0].at("ellipses");
  ASSERT_EQ(ellipses.size(), 1u);
  EXPECT_FLOAT_EQ(ellipses[0].at("cy").get<float>(), detector.features().ellipses[0].cy);
  EXPECT_GT(ellipses[0].at("cy").get<float>(), 480.f) << "its centre lies below the frame";
  // On the ground (soccer_vision_3d_msgs names): the circle where it was painted, its diameter
  // the rules', every point with its covariance.
  const json ground = read_json(out)["images"][0].at("ground");
  ASSERT_EQ(ground.at("ellipses").size(), 1u);
  const json& circle = ground["ellipses"][0];
  EXPECT_NEAR(circle.at("center").at("position").at("x").get<double>(), 0.8, 0.05);
  EXPECT_NEAR(circle["center"]["position"].at("y").get<double>(), 0.0, 0.05);
  EXPECT_NEAR(circle.at("diameter").get<double>(), 1.5, 0.05);
  EXPECT_EQ(circle.at("center_covariance").size(), 3u);
  EXPECT_GT(circle["center_covariance"][0].get<double>(), 0);
  for (const json& s : ground.at("segments")) {
    EXPECT_EQ(s.at("start").at("z").get<double>(), 0.0);
    EXPECT_GT(s["start"].at("x").get<double>(), 0) << "in front of the camera";
  }
  EXPECT_TRUE(ground.at("field_boundary").contains("points"));
  const CliRun plain = run({"detect", "--features", "--json", out.string(), path.string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_FALSE(read_json(out)["images"][0].contains("ground")) << "no camera, no ground";

  json bad = fieldlines::to_json(camera);
  bad["height_m"] = -1;
  file = write_bytes("camera.json", bad.dump());
  CliRun r = run({"detect", "--camera", file.string(), path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("height"), std::string::npos) << r.err;
  bad = fieldlines::to_json(camera);
  bad.erase("fx");
  file = write_bytes("camera.json", bad.dump());
  r = run({"detect", "--camera", file.string(), path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'fx'"), std::string::npos) << r.err;
  file = write_bytes("camera.json", "{\"format\": \"fieldlines-camera\", ");
  r = run({"detect", "--camera", file.string(), path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("malformed JSON"), std::string::npos) << r.err;
  r = run({"detect", "--camera", (dir_ / "none.json").string(), path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("none.json"), std::string::npos) << r.err;
}

TEST_F(CliDetect, FoldersAreSortedAndThreadsKeepTheInputOrder) {
  std::vector<std::string> names;
  for (int i = 0; i < 7; ++i) {
    const std::string name = "frame_" + std::string(1, static_cast<char>('g' - i)) + ".png";  // written out of order
    write_image(fs::path("batch") / name, synthetic_field(320, 240, i * 7));
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  const fs::path single = write_image("single.png", synthetic_field(200, 150, 3));
  const fs::path one = dir_ / "one.json", two = dir_ / "two.json";
  // An explicit file after the folder stays after it.
  ASSERT_EQ(run({"detect", "--quiet", "--json", one.string(), (dir_ / "batch").string(), single.string()}).exit_code, 0);
  const CliRun r = run({"detect", "--threads", "3", "--json", two.string(), (dir_ / "batch").string(), single.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  names.push_back("single.png");
  const json a = read_json(one), b = read_json(two);
  EXPECT_EQ(image_names(a), names);
  EXPECT_EQ(image_names(b), names);
  // Same segments whatever the thread count (timings aside).
  for (std::size_t i = 0; i < names.size(); ++i)
    EXPECT_EQ(a["images"][i]["segments"], b["images"][i]["segments"]) << names[i];
  // --quiet printed nothing; the default prints one line per image plus a total.
  EXPECT_NE(r.out.find(std::to_string(names.size()) + " images"), std::string::npos) << r.out;
}

TEST_F(CliDetect, BadFilesAreReportedSkippedAndExitWith1) {
  write_image("mixed/a_good.png", synthetic_field(320, 240));
  write_bytes("mixed/b_corrupt.png", std::string(2000, '\x42'));
  write_bytes("mixed/c_empty.jpg", "");
  write_image("mixed/d_good.png", synthetic_field(320, 240, 5));
  fs::create_directories(dir_ / "empty_folder");
  const fs::path out = dir_ / "out.json";
  const CliRun r = run({"detect", "--json", out.string(), (dir_ / "mixed").string(),
                        (dir_ / "missing.png").string(), (dir_ / "empty_folder").string()});
  EXPECT_EQ(r.exit_code, 1);
  for (const char* msg : {"b_corrupt.png: not a decodable image", "c_empty.jpg: empty file",
                          "missing.png: no such file", "empty_folder: folder holds no image",
                          "4 of 6 inputs failed"})
    EXPECT_NE(r.err.find(msg), std::string::npos) << msg << "\n" << r.err;
  // The good images are still processed and written, the bad ones listed with their error.
  const json j = read_json(out);
  EXPECT_EQ(image_names(j), (std::vector<std::string>{"a_good.png", "d_good.png"}));
  ASSERT_EQ(j.at("errors").size(), 4u);
  for (const auto& e : j["errors"]) {
    EXPECT_FALSE(e.at("path").get<std::string>().empty());
    EXPECT_FALSE(e.at("error").get<std::string>().empty());
  }
}

TEST_F(CliDetect, UnusualImagesGetAResultOrAClearMessage) {
  const cv::Mat bgr = synthetic_field(320, 240);
  cv::Mat grey, bgra, deep;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
  bgr.convertTo(deep, CV_16U, 257.0);
  write_image("odd/grey.png", grey);
  write_image("odd/alpha.png", bgra);
  write_image("odd/deep.png", deep);
  write_image("odd/tiny.png", cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3)));
  write_image("odd/float.tiff", cv::Mat(20, 20, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)));
  // A PNG header claiming 60000 x 60000 pixels: refused before any pixel is allocated.
  std::string png = read_text(write_image("odd/huge.png", bgr));
  for (const std::size_t at : {16u, 20u}) {
    png[at] = 0;
    png[at + 1] = 0;
    png[at + 2] = static_cast<char>(60000 >> 8);
    png[at + 3] = static_cast<char>(60000 & 0xff);
  }
  write_bytes("odd/huge.png", png);
  const fs::path out = dir_ / "out.json";
  const CliRun r = run({"detect", "--json", out.string(), "--draw", (dir_ / "overlays").string(), (dir_ / "odd").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("float.tiff: unsupported pixel type 32-bit float 3-channel"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("huge.png: image is 60000x60000"), std::string::npos) << r.err;
  const json j = read_json(out);
  EXPECT_EQ(image_names(j), (std::vector<std::string>{"alpha.png", "deep.png", "grey.png", "tiny.png"}));
  for (const auto& img : j["images"]) {
    const std::string name = img["image"];
    if (name == "tiny.png") EXPECT_TRUE(img["segments"].empty());
    else EXPECT_FALSE(img["segments"].empty()) << name;
    // Grey has no colour: with the default thresholds no grey gradient is within the classes'
    // angles (>= 35 degrees from green-white, >= 54 from black-green), so all are "none".
    if (name == "grey.png") {
      for (const auto& s : img["segments"]) EXPECT_EQ(s["label"], "none");
    }
    // Every processed image, whatever its type, gets an 8-bit colour overlay of its size.
    const cv::Mat overlay = cv::imread((dir_ / "overlays" / name).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(overlay.empty()) << name;
    EXPECT_EQ(overlay.type(), CV_8UC3) << name;
    EXPECT_EQ(overlay.cols, img["width"].get<int>()) << name;
  }
}

TEST_F(CliDetect, LargeImageIsProcessed) {
  const fs::path big = write_image("big.jpg", synthetic_field(4000, 3000));
  const fs::path out = dir_ / "out.json";
  const CliRun r = run({"detect", "--json", out.string(), big.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = read_json(out);
  EXPECT_EQ(j["images"][0]["width"], 4000);
  EXPECT_FALSE(j["images"][0]["segments"].empty());
}

TEST_F(CliDetect, OverlaysAreNamedAfterTheirImagesWithoutClashes) {
  const fs::path a = write_image("one/frame.png", synthetic_field(320, 240));
  const fs::path b = write_image("two/frame.jpg", synthetic_field(320, 240, 9));
  const fs::path draw = dir_ / "draw";
  const CliRun r = run({"detect", "--draw", draw.string(), a.string(), b.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("overlays written to"), std::string::npos);
  const cv::Mat first = cv::imread((draw / "frame.png").string());
  const cv::Mat second = cv::imread((draw / "frame-2.png").string());
  ASSERT_FALSE(first.empty());
  ASSERT_FALSE(second.empty());
  EXPECT_EQ(first.size(), cv::Size(320, 240));
  // The overlay shows something on top of the image (segments and legend).
  EXPECT_GT(cv::norm(first, cv::imread(a.string()), cv::NORM_L1), 0.0);
  // Drawing into the images' own folder never overwrites an input.
  const cv::Mat before = cv::imread(a.string());
  ASSERT_EQ(run({"detect", "--draw", (dir_ / "one").string(), a.string()}).exit_code, 0);
  EXPECT_EQ(cv::norm(cv::imread(a.string()), before, cv::NORM_INF), 0.0);
  EXPECT_TRUE(fs::exists(dir_ / "one" / "frame-2.png"));
}

TEST_F(CliDetect, CsvIsTheReferenceFormatWithTheSameSegments) {
  const fs::path a = write_image("a.png", synthetic_field(640, 480));
  const fs::path b = write_image("b.png", synthetic_field(640, 480, 13));
  const fs::path csv = dir_ / "out.csv", js = dir_ / "out.json";
  const CliRun r = run({"detect", "--csv", csv.string(), "--json", js.string(), a.string(), b.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Read back with the library's reader: it converts B,G,R and the reference's y sign back.
  const auto rows = fieldlines::read_reference_csv(csv);
  const json j = read_json(js);
  std::size_t k = 0;
  for (const auto& img : j["images"]) {
    for (const auto& s : img["segments"]) {
      ASSERT_LT(k, rows.size());
      const auto& row = rows[k++];
      EXPECT_EQ(row.image, img["image"].get<std::string>());
      EXPECT_FLOAT_EQ(row.segment.x0, s["x0"].get<float>());
      EXPECT_FLOAT_EQ(row.segment.y1, s["y1"].get<float>());
      EXPECT_FLOAT_EQ(row.segment.saliency, s["saliency"].get<float>());
      for (std::size_t c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(row.segment.grad_x[c], s["grad_x"][c].get<float>());
        EXPECT_FLOAT_EQ(row.segment.grad_y[c], s["grad_y"][c].get<float>());
      }
      EXPECT_EQ(fieldlines::to_string(row.segment.label), s["label"].get<std::string>());
    }
  }
  EXPECT_EQ(k, rows.size());
  EXPECT_GT(rows.size(), 0u);
  // The file itself is in the reference's layout.
  EXPECT_EQ(read_text(csv).rfind("img_path,x0,y0,x1,y1,grad_Bx,grad_Gx,grad_Rx,grad_By,grad_Gy,grad_Ry,segment_length", 0), 0u);
}

TEST_F(CliDetect, ThresholdsFileChangesTheLabelsAndTheDetector) {
  const fs::path img = write_image("a.png", synthetic_field(640, 480));
  const fs::path base = dir_ / "base.json", strict = dir_ / "strict.json", short_lines = dir_ / "short.json";
  ASSERT_EQ(run({"detect", "--json", base.string(), img.string()}).exit_code, 0);

  // Classes that nothing can reach: same segments, all labelled none.
  fieldlines::ThresholdsFile file;
  file.thresholds.marking.thresholds.min_length = 1e5f;
  file.thresholds.boundary.thresholds.min_length = 1e5f;
  fieldlines::save_thresholds_file(dir_ / "strict_thresholds.json", file);
  const CliRun r = run({"detect", "--thresholds", (dir_ / "strict_thresholds.json").string(), "--json", strict.string(), img.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json a = read_json(base)["images"][0]["segments"], b = read_json(strict)["images"][0]["segments"];
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  bool any_marking = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    any_marking |= a[i]["label"] == "marking";
    EXPECT_EQ(b[i]["label"], "none");
    EXPECT_EQ(a[i]["x0"], b[i]["x0"]);
  }
  EXPECT_TRUE(any_marking);

  // Detector parameters come from the file too: lines longer than the image find nothing.
  fieldlines::ThresholdsFile longer;
  longer.detector.min_line_length = 2000;
  fieldlines::save_thresholds_file(dir_ / "long.json", longer);
  ASSERT_EQ(run({"detect", "--thresholds", (dir_ / "long.json").string(), "--json", short_lines.string(), img.string()}).exit_code, 0);
  EXPECT_TRUE(read_json(short_lines)["images"][0]["segments"].empty());

  // A broken thresholds file is fatal before any image is read, and names the file.
  const fs::path broken = write_bytes("broken.json", "{\"format\": ");
  const CliRun bad = run({"detect", "--thresholds", broken.string(), img.string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("broken.json"), std::string::npos) << bad.err;
}
