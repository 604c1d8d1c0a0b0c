// Bad-input matrix, images: every command that reads images (detect, bench, autolabel) on
// missing, empty, truncated, corrupt, unusual-type and extreme-size images. Rows already
// covered by cli_detect_test / image_io_test / cli_bench_test are listed in docs/bad_input.md
// and not repeated here.
#include <filesystem>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "bad_input_support.hpp"

namespace fs = std::filesystem;
using fieldlines::test::BadInputTest;
using fieldlines::test::read_text;
using fieldlines::test::synthetic_field;
using json = nlohmann::json;

namespace {

class BadImages : public BadInputTest {
 protected:
  // `fieldlines bench` on one good image plus `bad`: the bad one is skipped, exit 1.
  fieldlines::test::CliRun bench_with(const fs::path& bad) {
    return run({"bench", "--rounds", "1", "--repeat", "1", "--quiet", field_image("good.png").string(), bad.string()});
  }
  // Replaces the first image of a synthetic set copy with `contents` and runs autolabel on it.
  fieldlines::test::CliRun autolabel_with_first_image(const std::string& contents, std::string& first_name) {
    const fs::path set = synth_set("set");
    const fs::path first = set_images(set).front();
    first_name = first.filename().string();
    bytes(fs::relative(first, dir_).string(), contents);
    return run({"autolabel", set.string(), "--quiet", "-o", path("p.json").string()});
  }
};

// ---- detect: rows not in cli_detect_test ---------------------------------------------------

TEST_F(BadImages, DetectTruncatedPngIsReportedAndSkipped) {
  const fs::path bad = truncated_image("cut.png", 0.5);
  const auto r = run({"detect", "--quiet", field_image("good.png").string(), bad.string()});
  EXPECT_CLI_FAILS(r, 1, "cut.png: not a decodable image", "1 of 2 inputs failed");
}

TEST_F(BadImages, DetectTruncatedJpegIsReportedAndSkipped) {
  const fs::path bad = truncated_image("cut.jpg", 0.5);
  const auto r = run({"detect", "--quiet", bad.string()});
  EXPECT_CLI_FAILS(r, 1, "cut.jpg: ", "truncated");
}

TEST_F(BadImages, DetectOneByOneImageGivesNoSegments) {
  const fs::path tiny = image("one.png", cv::Mat(1, 1, CV_8UC3, cv::Scalar(1, 2, 3)));
  const auto r = run({"detect", "--json", path("o.json").string(), tiny.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_text(path("o.json")));
  EXPECT_EQ(j["images"][0]["width"], 1);
  EXPECT_TRUE(j["images"][0]["segments"].empty());
}

TEST_F(BadImages, DetectTenThousandSquareImageIsProcessed) {
  // A real 10000x10000 (100 Mpx, the load limit) image: flat carpet and one painted line.
  cv::Mat big(10000, 10000, CV_8UC1, cv::Scalar(90));
  cv::line(big, {500, 3000}, {9500, 3300}, cv::Scalar(250), 20);
  const fs::path p = path("big.png");
  ASSERT_TRUE(cv::imwrite(p.string(), big, {cv::IMWRITE_PNG_COMPRESSION, 1}));
  big.release();
  // About 2 s in all (1.3 s in the CLI, 1.4 GB peak); no timing assertion, see docs/bad_input.md.
  const auto r = run({"detect", "--json", path("o.json").string(), p.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_text(path("o.json")));
  EXPECT_EQ(j["images"][0]["width"], 10000);
  EXPECT_FALSE(j["images"][0]["segments"].empty());
}

TEST_F(BadImages, DetectJustOverThePixelLimitIsRefusedFromTheHeader) {
  // 10001x10000 > 100 Mpx: the header says so, nothing is decoded.
  std::string png = read_text(field_image("over.png"));
  const auto put = [&](std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) png[at + static_cast<std::size_t>(k)] = static_cast<char>((v >> (24 - 8 * k)) & 0xff);
  };
  put(16, 10001);
  put(20, 10000);
  bytes("over.png", png);
  const auto r = run({"detect", "--quiet", path("over.png").string()});
  EXPECT_CLI_FAILS(r, 1, "over.png: image is 10001x10000");
}

// ---- bench ---------------------------------------------------------------------------------

TEST_F(BadImages, BenchMissingImage) {
  EXPECT_CLI_FAILS(bench_with(path("missing.png")), 1, "missing.png: no such file");
}

TEST_F(BadImages, BenchEmptyImage) { EXPECT_CLI_FAILS(bench_with(bytes("empty.png", "")), 1, "empty.png: empty file"); }

TEST_F(BadImages, BenchTruncatedImage) {
  EXPECT_CLI_FAILS(bench_with(truncated_image("cut.png", 0.5)), 1, "cut.png: not a decodable image");
}

TEST_F(BadImages, BenchFloatImage) {
  const fs::path f = image("float.tiff", cv::Mat(20, 20, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)));
  EXPECT_CLI_FAILS(bench_with(f), 1, "float.tiff: unsupported pixel type 32-bit float 3-channel");
}

TEST_F(BadImages, BenchGreyAlphaAndDeepImagesAreTimed) {
  const cv::Mat bgr = synthetic_field(320, 240);
  cv::Mat grey, bgra, deep;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
  bgr.convertTo(deep, CV_16U, 257.0);
  const auto r = run({"bench", "--rounds", "1", "--repeat", "1", "--quiet", "--json", path("b.json").string(),
                      image("g.png", grey).string(), image("a.png", bgra).string(), image("d.png", deep).string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json::parse(read_text(path("b.json"))).at("images"), 3);
}

TEST_F(BadImages, BenchOneByOneImageDoesNotCrashThePeers) {
  // OpenCV's own detectors get the 1x1 frame too; none may crash on it.
  const fs::path tiny = image("one.png", cv::Mat(1, 1, CV_8UC3, cv::Scalar(1, 2, 3)));
  const auto r =
      run({"bench", "--rounds", "1", "--repeat", "1", "--quiet", "--json", path("b.json").string(), tiny.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(read_text(path("b.json")));
  EXPECT_EQ(j.at("images"), 1);
  for (const auto& d : j.at("detectors")) EXPECT_EQ(d.at("segments_per_image"), 0) << d;
}

// ---- autolabel -----------------------------------------------------------------------------

TEST_F(BadImages, AutolabelEmptyImageIsSkipped) {
  std::string name;
  const auto r = autolabel_with_first_image("", name);
  EXPECT_CLI_FAILS(r, 1, name + ": empty file");
  // The other image is still labelled and saved.
  EXPECT_EQ(json::parse(read_text(path("p.json"))).at("images").size(), 1u);
}

TEST_F(BadImages, AutolabelCorruptImageIsSkipped) {
  std::string name;
  const auto r = autolabel_with_first_image(std::string(3000, 'x'), name);
  EXPECT_CLI_FAILS(r, 1, name + ": not a decodable image");
}

TEST_F(BadImages, AutolabelTruncatedImageIsSkipped) {
  const fs::path set = synth_set("set");
  const fs::path first = set_images(set).front();
  const std::string full = read_text(first);
  bytes(fs::relative(first, dir_).string(), full.substr(0, full.size() / 2));
  const auto r = run({"autolabel", set.string(), "--quiet", "-o", path("p.json").string()});
  EXPECT_CLI_FAILS(r, 1, first.filename().string() + ": not a decodable image");
}

TEST_F(BadImages, AutolabelFloatImageIsSkipped) {
  const fs::path set = synth_set("set");
  const fs::path first = set_images(set).front();
  // Same name, so the ground truth still matches. PNG cannot hold float pixels, so TIFF content
  // goes under the .png name (OpenCV decodes by content, not by extension).
  std::vector<unsigned char> tiff;
  ASSERT_TRUE(cv::imencode(".tiff", cv::Mat(20, 20, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)), tiff));
  bytes(fs::relative(first, dir_).string(), std::string(tiff.begin(), tiff.end()));
  const auto r = run({"autolabel", set.string(), "--quiet", "-o", path("p.json").string()});
  EXPECT_CLI_FAILS(r, 1, first.filename().string() + ": unsupported pixel type 32-bit float");
}

TEST_F(BadImages, AutolabelGreyDeepAndTinyImagesAreLabelled) {
  // Same loader as detect: grey and 16-bit frames are labelled, a 1x1 frame has no segments.
  const fs::path set = synth_set("set");
  const auto images = set_images(set);
  ASSERT_EQ(images.size(), 2u);
  const cv::Mat bgr = cv::imread(images[0].string(), cv::IMREAD_COLOR);
  cv::Mat grey, deep;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::imread(images[1].string(), cv::IMREAD_COLOR).convertTo(deep, CV_16U, 257.0);
  image(fs::relative(images[0], dir_).string(), grey);
  image(fs::relative(images[1], dir_).string(), deep);
  auto r = run({"autolabel", set.string(), "--quiet", "-o", path("p.json").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json j = json::parse(read_text(path("p.json")));
  ASSERT_EQ(j.at("images").size(), 2u);
  EXPECT_FALSE(j["images"][1]["segments"].empty());  // the 16-bit frame finds the same lines
  image(fs::relative(images[0], dir_).string(), cv::Mat(1, 1, CV_8UC3, cv::Scalar(1, 2, 3)));
  r = run({"autolabel", set.string(), "--quiet", "-o", path("q.json").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = json::parse(read_text(path("q.json")));
  EXPECT_TRUE(j["images"][0]["segments"].empty());
}

TEST_F(BadImages, AutolabelCorruptGroundTruthIsSkipped) {
  const fs::path set = synth_set("set");
  const fs::path first = set_images(set).front();
  const fs::path truth = set / "truth" / (first.stem().string() + ".json");
  ASSERT_TRUE(fs::exists(truth));
  bytes(fs::relative(truth, dir_).string(), "{\"lines\": [");
  const auto r = run({"autolabel", set.string(), "--quiet", "-o", path("p.json").string()});
  EXPECT_CLI_FAILS(r, 1, truth.filename().string());
}

TEST_F(BadImages, AutolabelWithEveryImageFailingKeepsThePreviousProject) {
  const fs::path set = synth_set("set");
  const fs::path previous = project("previous.json", 9);
  const std::string before = read_text(previous);
  for (const fs::path& img : set_images(set)) bytes(fs::relative(img, dir_).string(), "");
  const auto r = run({"autolabel", set.string(), "--quiet", "-o", previous.string()});
  EXPECT_CLI_FAILS(r, 2, "empty file", "no image could be labelled", previous.string() + " not written");
  EXPECT_EQ(read_text(previous), before);
}

TEST_F(BadImages, AutolabelMissingSetFolder) {
  const auto r = run({"autolabel", path("nowhere").string(), "-o", path("p.json").string()});
  EXPECT_CLI_FAILS(r, 2, "nowhere: not a folder");
  EXPECT_FALSE(fs::exists(path("p.json")));
}

}  // namespace
