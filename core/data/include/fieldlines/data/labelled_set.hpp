#pragma once
// The flat labelled view of a Project (Project::labelled()) that training, evaluation and splits
// work on: every segment with a human label (Unlabelled ones are dropped) and the image it came
// from, in project order. A view, not a document: the Project (fieldlines/data/project.hpp,
// loaded from either DATA format by data_file.hpp) is what is saved and edited.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct LabelledSet {
  std::vector<std::string> images;       // distinct image names, in first-seen order
  std::vector<Segment> segments;         // segment.label = the human label (never Unlabelled)
  std::vector<std::uint32_t> image_of;   // per segment: index into `images`

  std::size_t size() const { return segments.size(); }
  // Appends one labelled segment (ignored when Unlabelled); `image` is looked up or added.
  void add(const std::string& image, const Segment& segment);
  // The rows at `indices` (in that order), keeping their image names.
  LabelledSet subset(std::span<const std::size_t> indices) const;
  // Appends another set (images with equal names are merged).
  void append(const LabelledSet& other);
  // Count of segments per human label.
  std::size_t count(Label label) const;
};

// The labelled rows in file order. For rows whose images are contiguous (every file we write,
// and the reference's own) this equals project_from_reference_rows(rows).labelled().
LabelledSet labelled_set_from_rows(std::span<const ReferenceRow> rows);

}  // namespace fieldlines
