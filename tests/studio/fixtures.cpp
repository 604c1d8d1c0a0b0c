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
