#include "fieldlines/data/labelled_set.hpp"

#include <algorithm>
#include <unordered_map>

namespace fieldlines {

void LabelledSet::add(const std::string& image, const Segment& segment) {
  if (segment.label == Label::Unlabelled) return;
  // Linear search from the back: rows of one image are almost always consecutive.
  std::uint32_t idx = static_cast<std::uint32_t>(images.size());
  if (!images.empty() && images.back() == image) {
    idx = idx - 1;
  } else {
    const auto it = std::find(images.begin(), images.end(), image);
    if (it != images.end()) idx = static_cast<std::uint32_t>(it - images.begin());
    else images.push_back(image);
  }
  segments.push_back(segment);
  image_of.push_back(idx);
}

LabelledSet LabelledSet::subset(std::span<const std::size_t> indices) const {
  LabelledSet out;
  for (const std::size_t i : indices) out.add(images[image_of[i]], segments[i]);
  return out;
}

void LabelledSet::append(const LabelledSet& other) {
  for (std::size_t i = 0; i < other.size(); ++i) add(other.images[other.image_of[i]], other.segments[i]);
}

std::size_t LabelledSet::count(Label label) const {
  return static_cast<std::size_t>(std::count_if(segments.begin(), segments.end(),
                                                [&](const Segment& s) { return s.label == label; }));
}

LabelledSet labelled_set_from_rows(std::span<const ReferenceRow> rows) {
  LabelledSet out;
  for (const ReferenceRow& r : rows) out.add(r.image, r.segment);
  return out;
}

}  // namespace fieldlines
