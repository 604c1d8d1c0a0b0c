#pragma once
// Running the built `fieldlines` binary from tests, in a private temporary folder.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "shared_data.hpp"

namespace fieldlines::test {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs `fieldlines <args>` with stdout and stderr captured in files under `dir`.
inline CliRun run_cli(const std::vector<std::string>& args, const std::filesystem::path& dir) {
  std::string cmd = shell_quote(cli_path().string());
  for (const auto& a : args) {
    cmd += ' ';
    cmd += shell_quote(a);
  }
  const auto out = dir / "cli_stdout.txt", err = dir / "cli_stderr.txt";
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on " >" + std::string&&.
  cmd += " >";
  cmd += shell_quote(out.string());
  cmd += " 2>";
  cmd += shell_quote(err.string());
  cmd += " </dev/null";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// A fixture owning a fresh temporary folder named after the test.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("fieldlines_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes an image (format from the extension) or raw bytes under the folder, making parents.
  std::filesystem::path write_image(const std::filesystem::path& relative, const cv::Mat& img) const {
    const auto p = dir_ / relative;
    std::filesystem::create_directories(p.parent_path());
    EXPECT_TRUE(cv::imwrite(p.string(), img)) << p;
    return p;
  }
  std::filesystem::path write_bytes(const std::filesystem::path& relative, const std::string& bytes) const {
    const auto p = dir_ / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

  std::filesystem::path dir_;
};

// A synthetic field: green carpet, a black wall across the top (a field boundary) and white
// painted lines (field markings), drawn with cv::line. `shift` moves the lines so images differ.
inline cv::Mat synthetic_field(int width, int height, int shift = 0) {
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(50, 140, 40));
  // The wall edge is slightly tilted, as in a real camera frame.
  const std::vector<cv::Point> wall{{0, 0}, {width - 1, 0}, {width - 1, height / 6 + height / 50}, {0, height / 6}};
  cv::fillConvexPoly(img, wall, cv::Scalar(20, 20, 20));
  const int t = std::max(3, width / 100);
  cv::line(img, {width / 12, height / 2 + shift}, {width - width / 12, height / 2 + shift}, {255, 255, 255}, t, cv::LINE_AA);
  cv::line(img, {width / 3 + shift, height / 3}, {width / 4 + shift, height - height / 12}, {255, 255, 255}, t, cv::LINE_AA);
  // Camera-like noise (fixed seed): on a noiseless synthetic step the smoothed gradient ties
  // on both sides of the edge, and edge drawing finds no anchor there.
  cv::Mat noise(img.size(), CV_16SC3);
  cv::RNG rng(12345 + static_cast<std::uint64_t>(shift));
  rng.fill(noise, cv::RNG::NORMAL, 0, 4);
  cv::Mat noisy;
  img.convertTo(noisy, CV_16SC3);
  noisy += noise;
  noisy.convertTo(img, CV_8UC3);
  return img;
}

}  // namespace fieldlines::test
