#include "fixtures.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace studio_test {

cv::Mat field_image(int width, int height, const std::vector<fieldlines::Segment>& lines) {
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(40, 140, 40));
  for (const auto& s : lines) {
    cv::line(image, {static_cast<int>(std::lround(s.x0)), static_cast<int>(std::lround(s.y0))},
             {static_cast<int>(std::lround(s.x1)), static_cast<int>(std::lround(s.y1))}, cv::Scalar(255, 255, 255), 5);
  }
  return image;
}

namespace {
std::array<double, 3> lab(std::array<int, 3> rgb) {
  const auto linear = [](int c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const double r = linear(rgb[0]), g = linear(rgb[1]), b = linear(rgb[2]);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}
}  // namespace

double delta_e76(std::array<int, 3> a, std::array<int, 3> b) {
  const auto p = lab(a), q = lab(b);
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

double lightness(std::array<int, 3> rgb) { return lab(rgb)[0]; }

std::vector<fieldlines::Segment> grid_segments(int width, int height, int count) {
  std::vector<fieldlines::Segment> out;
  const int cols = std::max(1, static_cast<int>(std::ceil(std::sqrt(count * 1.0 * width / height / 4))));
  const int rows = (count + cols - 1) / cols;
  const float cell_w = static_cast<float>(width) / static_cast<float>(cols);
  const float cell_h = static_cast<float>(height) / static_cast<float>(rows);
  for (int i = 0; i < count; ++i) {
    const int r = i / cols, c = i % cols;
    fieldlines::Segment s;
    s.x0 = static_cast<float>(c) * cell_w + cell_w * 0.1f;
    s.x1 = static_cast<float>(c) * cell_w + cell_w * 0.9f;
    s.y0 = s.y1 = std::floor(static_cast<float>(r) * cell_h + cell_h * 0.5f);
    s.saliency = 200;  // above both classes' default min_length
    if (i % 2 == 0) {
      s.grad_y = {-200, -100, -200};  // white above green: marking (two-sided)
    } else {
      s.grad_y = {0, 150, 0};  // black above green: boundary
    }
    s.label = fieldlines::Label::Unlabelled;
    out.push_back(s);
  }
  return out;
}

TempDir::TempDir(const std::string& tag) {
  std::random_device rd;
  path_ = std::filesystem::temp_directory_path() /
          ("fieldlines-studio-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::filesystem::path write_project(const std::filesystem::path& folder, int images, int segments_per_image,
                                    int width, int height) {
  fieldlines::Project project;
  for (int i = 0; i < images; ++i) {
    const auto segments = grid_segments(width, height, segments_per_image);
    std::string name = i < 10 ? "img_0" : "img_";
    name += std::to_string(i);
    name += ".png";
    cv::imwrite((folder / name).string(), field_image(width, height, segments));
    project.images.push_back({name, segments, 1.0});
  }
  const auto file = folder / "project.json";
  project.save(file);
  return file;
}

}  // namespace studio_test
