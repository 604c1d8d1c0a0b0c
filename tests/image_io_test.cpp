// Loading images: every kind of bad file gives a fieldlines::Error naming the file; unusual but
// valid images (grey, BGRA, 16-bit, tiny) load and go through the detector without a crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/image_io.hpp"

namespace fs = std::filesystem;
using fieldlines::Error;

namespace {

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("fieldlines_image_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write_bytes(const std::string& name, const std::string& bytes) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  fs::path write_image(const std::string& name, const cv::Mat& image) const {
    const fs::path p = dir_ / name;
    EXPECT_TRUE(cv::imwrite(p.string(), image)) << p;
    return p;
  }
  static std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  fs::path dir_;
};

// Green field, white line: an image the detector has something to find in.
cv::Mat field(int w, int h) {
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(60, 140, 40));
  cv::line(img, {w / 10, h / 2}, {w - w / 10, h / 2 + h / 10}, {255, 255, 255}, 5);
  return img;
}

// Expects load_image to throw an Error whose message names the file and contains `reason`.
void expect_load_error(const fs::path& path, const std::string& reason,
                       const fieldlines::ImageLoadParams& params = {}) {
  try {
    (void)fieldlines::load_image(path, params);
    ADD_FAILURE() << "no error for " << path;
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    EXPECT_NE(what.find(reason), std::string::npos) << what;
  }
}

}  // namespace

TEST_F(ImageIo, LoadsColourImageWithItsPixels) {
  const cv::Mat img = field(64, 48);
  const cv::Mat loaded = fieldlines::load_image(write_image("a.png", img));
  ASSERT_EQ(loaded.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(loaded, img, cv::NORM_INF), 0.0);
}

TEST_F(ImageIo, KeepsGreyAlphaAnd16BitAndTheDetectorAcceptsThem) {
  const cv::Mat bgr = field(160, 120);
  cv::Mat grey, bgra, deep;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
  bgr.convertTo(deep, CV_16U, 257.0);
  fieldlines::LineDetector detector;
  for (const auto& [name, image] : {std::pair{"grey.png", grey}, {"alpha.png", bgra}, {"deep.png", deep}}) {
    const cv::Mat loaded = fieldlines::load_image(write_image(name, image));
    EXPECT_EQ(loaded.type(), image.type()) << name;
    EXPECT_NO_THROW((void)detector.detect(loaded)) << name;
    const cv::Mat shown = fieldlines::to_bgr8(loaded);
    EXPECT_EQ(shown.type(), CV_8UC3) << name;
    EXPECT_EQ(shown.size(), bgr.size()) << name;
  }
  // 16-bit is scaled back to the 8-bit values it was made from.
  EXPECT_LE(cv::norm(fieldlines::to_bgr8(deep), bgr, cv::NORM_INF), 1.0);
}

TEST_F(ImageIo, TinyImagesLoadAndGiveNoSegments) {
  fieldlines::LineDetector detector;
  // Below the 3x3 gradient window, then below the 7x7 smoothing kernel (with a white stripe).
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(2, 2), cv::Size(2, 50), cv::Size(50, 2), cv::Size(3, 3),
                              cv::Size(5, 5), cv::Size(6, 200)}) {
    cv::Mat img(size, CV_8UC3, cv::Scalar(40, 140, 50));
    img.col(size.width / 2).setTo(cv::Scalar(255, 255, 255));
    const cv::Mat loaded = fieldlines::load_image(write_image("tiny.png", img));
    EXPECT_EQ(loaded.size(), size);
    EXPECT_TRUE(detector.detect(loaded).empty()) << size;
  }
}

TEST_F(ImageIo, MissingFileFolderAndEmptyFileAreNamed) {
  expect_load_error(dir_ / "nope.png", "no such file");
  fs::create_directories(dir_ / "folder.png");
  expect_load_error(dir_ / "folder.png", "is a folder");
  expect_load_error(write_bytes("empty.png", ""), "empty file");
}

TEST_F(ImageIo, CorruptAndNonImageFilesAreErrorsNotCrashes) {
  expect_load_error(write_bytes("noise.png", std::string(4096, '\x5a')), "not a decodable image");
  expect_load_error(write_bytes("notes.jpg", "this is text, not a JPEG\n"), "not a decodable image");
  // A real PNG cut after its header: the header is fine, the pixel data is missing.
  const std::string png = read_all(write_image("whole.png", field(200, 150)));
  expect_load_error(write_bytes("cut.png", png.substr(0, 60)), "not a decodable image");
  // A JPEG cut in half: libjpeg would fill the rest with grey and call it a success.
  const std::string jpg = read_all(write_image("whole.jpg", field(200, 150)));
  EXPECT_EQ(fieldlines::load_image(write_bytes("copy.jpg", jpg)).size(), cv::Size(200, 150));
  expect_load_error(write_bytes("half.jpg", jpg.substr(0, jpg.size() / 2)), "truncated JPEG");
  expect_load_error(write_bytes("headers.jpg", jpg.substr(0, 100)), "truncated JPEG");
  // Bytes appended after a complete JPEG (as some cameras do) are fine.
  EXPECT_NO_THROW((void)fieldlines::load_image(write_bytes("trailer.jpg", jpg + std::string(3000, '\x11'))));
  // A PNG whose pixel data is overwritten with garbage.
  std::string broken = png;
  for (std::size_t i = 100; i < broken.size(); i += 7) broken[i] = static_cast<char>(broken[i] ^ 0x5c);
  expect_load_error(write_bytes("garbled.png", broken), "not a decodable image");
}

TEST_F(ImageIo, HugeImageIsRefusedFromItsHeaderBeforeDecoding) {
  // A real PNG header (signature + IHDR) that claims 100000 x 100000 pixels, and nothing else:
  // decoding it would need 30 GB, so the size must be caught from the header.
  std::string png = read_all(write_image("small.png", field(8, 8)));
  auto put32 = [&](std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) png[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (24 - 8 * i)) & 0xff);
  };
  put32(16, 100000);
  put32(20, 100000);
  const fs::path huge = write_bytes("huge.png", png);
  ASSERT_EQ(fieldlines::probe_image_size(huge), cv::Size(100000, 100000));
  expect_load_error(huge, "100000x100000 = 10000000000 pixels, more than the limit");
}

TEST_F(ImageIo, PixelLimitAlsoAppliesToFormatsWithoutAHeaderProbe) {
  const fs::path tiff = write_image("big.tiff", field(200, 100));
  EXPECT_FALSE(fieldlines::probe_image_size(tiff).has_value());
  fieldlines::ImageLoadParams params;
  params.max_pixels = 19'999;
  expect_load_error(tiff, "more than the limit of 19999", params);
  params.max_pixels = 20'000;
  EXPECT_EQ(fieldlines::load_image(tiff, params).size(), cv::Size(200, 100));
}

TEST_F(ImageIo, UnsupportedPixelTypeIsNamed) {
  cv::Mat floats(20, 30, CV_32FC3, cv::Scalar(0.5, 0.25, 1.0));
  expect_load_error(write_image("float.tiff", floats), "unsupported pixel type 32-bit float 3-channel");
}

TEST_F(ImageIo, ProbeReadsTheSizeOfCommonFormats) {
  const cv::Mat img = field(123, 45);
  for (const char* name : {"a.png", "a.jpg", "a.bmp", "a.ppm", "a.pgm"}) {
    cv::Mat out = img;
    if (std::string(name) == "a.pgm") cv::cvtColor(img, out, cv::COLOR_BGR2GRAY);
    EXPECT_EQ(fieldlines::probe_image_size(write_image(name, out)), cv::Size(123, 45)) << name;
  }
  EXPECT_FALSE(fieldlines::probe_image_size(write_bytes("x.png", "garbage")).has_value());
  EXPECT_FALSE(fieldlines::probe_image_size(dir_ / "missing.png").has_value());
}

TEST_F(ImageIo, ListsImagesSortedAndSkipsEverythingElse) {
  const cv::Mat img = field(16, 16);
  write_image("b.png", img);
  write_image("a.JPG", img);
  write_image("c.bmp", img);
  write_image(".hidden.png", img);
  write_bytes("readme.txt", "not an image");
  fs::create_directories(dir_ / "sub.png");
  const auto listed = fieldlines::list_images(dir_);
  std::vector<std::string> names;
  for (const auto& p : listed) names.push_back(p.filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"a.JPG", "b.png", "c.bmp"}));
  EXPECT_THROW((void)fieldlines::list_images(dir_ / "b.png"), Error);
  EXPECT_THROW((void)fieldlines::list_images(dir_ / "missing"), Error);
  EXPECT_TRUE(fieldlines::has_image_extension("x.TIFF"));
  EXPECT_FALSE(fieldlines::has_image_extension("x.csv"));
}
