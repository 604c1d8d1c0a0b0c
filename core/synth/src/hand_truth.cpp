#include "fieldlines/synth/hand_truth.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/json_file.hpp"

namespace fieldlines::synth {
namespace {

constexpr JsonFileFormat kFormat{"schema", "fieldlines-hand-truth", "hand-made truth", "hand truth",
                                 HandTruth::kVersion, JsonFileFormat::Newer::UpdateFieldlines};

}  // namespace

HandTruth hand_truth_from_json(const nlohmann::json& j, const std::string& ctx) {
  require_json_file_format(j, kFormat, ctx);
  HandTruth h;
  h.image = json_field<std::string>(j, "image", ctx);
  h.width = json_field<int>(j, "width", ctx);
  h.height = json_field<int>(j, "height", ctx);
  if (h.width <= 0 || h.height <= 0) throw Error(ctx + ": 'width' and 'height' must be positive");
  h.truth.image = h.image;
  h.truth.intrinsics.width = h.width;
  h.truth.intrinsics.height = h.height;
  const auto features = json_field<nlohmann::json>(j, "features", ctx);
  if (!features.is_array()) throw Error(ctx + ": 'features' must be an array");
  for (std::size_t i = 0; i < features.size(); ++i) {
    const std::string fctx = ctx + ": features[" + std::to_string(i) + "]";
    const auto label = json_field<std::string>(features[i], "label", fctx);
    std::vector<TruthPoint> points = truth_points_from_json(features[i], fctx);
    if (label == "field_boundary") {
      h.field_boundary.push_back(std::move(points));
      continue;
    }
    TruthFeature f;
    if (label == "marking") f.label = Label::Marking;
    else if (label == "boundary_edge") f.label = Label::Boundary;
    else throw Error(fctx + ": label must be 'marking', 'boundary_edge' or 'field_boundary', got '" + label + "'");
    if (f.label == Label::Boundary)
      for (TruthPoint& p : points) p.width = 0;  // an edge, not a strip
    f.name = json_field<std::string>(features[i], "name", fctx);
    f.points = std::move(points);
    h.truth.features.push_back(std::move(f));
  }
  return h;
}

std::vector<float> field_boundary_rows(const HandTruth& hand) {
  std::vector<float> rows(static_cast<std::size_t>(std::max(hand.width, 0)), -1.f);
  for (const std::vector<TruthPoint>& line : hand.field_boundary)
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const TruthPoint& a = line[i];
      const TruthPoint& b = line[i + 1];
      if (!(b.x > a.x)) continue;  // a vertical step: its neighbours give the rows
      // Clamped as floats: a point far off the frame must not overflow the int.
      const int first = static_cast<int>(std::ceil(std::clamp(a.x, 0.f, float(hand.width))));
      const int last = static_cast<int>(std::floor(std::clamp(b.x, -1.f, float(hand.width - 1))));
      for (int x = first; x <= last; ++x)
        rows[static_cast<std::size_t>(x)] = a.y + (b.y - a.y) * (static_cast<float>(x) - a.x) / (b.x - a.x);
    }
  return rows;
}

HandTruth load_hand_truth(const std::filesystem::path& path) {
  return hand_truth_from_json(parse_json_text(read_file(path), path.string()), path.string());
}

std::vector<std::filesystem::path> list_hand_truth(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) throw Error(dir.string() + ": not a folder");
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".json") out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  if (out.empty()) throw Error(dir.string() + ": no hand-truth file (<name>.json) in it");
  return out;
}

}  // namespace fieldlines::synth
