#pragma once
// Per-class detection counts and scores of a threshold set against human labels.
//
// For a class C: TP = predicted C and labelled C; FP = predicted C, labelled otherwise;
// FN = labelled C, predicted otherwise. Precision/recall/F1 are 0 when undefined (0/0).
#include <span>
#include <string>
#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/data/labelled_set.hpp"

namespace fieldlines {

struct ClassCounts {
  long tp = 0, fp = 0, fn = 0;
  // No labelled and no predicted segment of the class: its figures are undefined ("n/a",
  // JSON null), not 0. The ratios below return 0 for 0/0 only so arithmetic never sees NaN.
  bool empty() const { return tp + fp + fn == 0; }
  double precision() const;
  double recall() const;
  double f1() const;
  double fbeta(double beta) const;
  ClassCounts& operator+=(const ClassCounts& o);
  bool operator==(const ClassCounts&) const = default;
};

struct Counts {
  ClassCounts marking, boundary;
  Counts& operator+=(const Counts& o);
  bool operator==(const Counts&) const = default;
};

// Adds one segment's outcome: `truth` is the human label, `predicted` the classifier's.
void tally(Counts& counts, Label truth, Label predicted);

struct ImageCounts {
  std::string image;
  Counts counts;
};

struct Evaluation {
  Counts total;
  std::vector<ImageCounts> per_image;  // in the set's image order
};

Evaluation evaluate(const LabelledSet& data, const Thresholds& thresholds);
// The totals alone over plain segments (their .label is the truth; unlabelled ones are skipped).
Counts count_labelled(std::span<const Segment> segments, const Thresholds& thresholds);

}  // namespace fieldlines
