#pragma once
// Test fixtures for the studio: synthetic field pictures with known segments, saved as a project.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/segment.hpp"

namespace studio_test {

// Green carpet with the given segments drawn as 5 px white lines (BGR, 8-bit).
cv::Mat field_image(int width, int height, const std::vector<fieldlines::Segment>& lines);

// CIE76 colour difference (Delta-E in L*a*b*, sRGB D65) and lightness L*: how far apart two
// colours look. ~2 is just noticeable; > 50 reads as a different colour at a glance.
double delta_e76(std::array<int, 3> rgb_a, std::array<int, 3> rgb_b);
double lightness(std::array<int, 3> rgb);

// `count` horizontal segments in a grid over a width x height image, with gradients that the
// default thresholds classify: even indices as markings (white-green), odd as boundaries
// (black above green). Labels are Unlabelled.
std::vector<fieldlines::Segment> grid_segments(int width, int height, int count);

// A fresh empty folder under the system temp folder, removed by the destructor.
class TempDir {
 public:
  explicit TempDir(const std::string& tag);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Writes `images` field pictures (img_00.png ...) with `segments_per_image` grid segments each
// into `folder` and saves a project over them as folder/project.json. Returns the project file.
std::filesystem::path write_project(const std::filesystem::path& folder, int images, int segments_per_image,
                                    int width = 320, int height = 240);

}  // namespace studio_test
