#pragma once
// Test helper: reads reference/segments_elsed_ssl.csv (the reference implementation's output).
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::test {

// Per image file name, the reference segments converted to our conventions (RGB, image-down y).
inline std::map<std::string, std::vector<Segment>> read_reference_segments(const std::filesystem::path& csv) {
  std::map<std::string, std::vector<Segment>> out;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string image, cell;
    std::getline(ss, image, ',');
    std::vector<double> v;
    while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
    if (v.size() != 12) continue;
    Segment s;
    s.x0 = static_cast<float>(v[0]), s.y0 = static_cast<float>(v[1]);
    s.x1 = static_cast<float>(v[2]), s.y1 = static_cast<float>(v[3]);
    for (int c = 0; c < 3; ++c) {
      s.grad_x[2 - c] = static_cast<float>(v[4 + c]);
      s.grad_y[2 - c] = -static_cast<float>(v[7 + c]);
    }
    s.saliency = static_cast<float>(v[10]);
    s.label = static_cast<Label>(static_cast<int>(v[11]));
    out[image].push_back(s);
  }
  return out;
}

}  // namespace fieldlines::test
