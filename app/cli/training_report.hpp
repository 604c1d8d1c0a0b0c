#pragma once
// Text and JSON forms of evaluation counts shared by train, eval and sweep, and of train's
// k-fold cross-validation.
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/train/metrics.hpp"
#include "fieldlines/train/splits.hpp"
#include "fieldlines/train/training.hpp"

namespace fieldlines::cli {

// {"tp", "fp", "fn", "precision", "recall", "f1"}
nlohmann::json class_json(const ClassCounts& c);
// {"marking": {...}, "boundary": {...}}
nlohmann::json counts_json(const Counts& c);
// One aligned line: "<label> marking  TP FP FN P R F1 | boundary ..."
void print_counts(std::FILE* out, const std::string& label, const Counts& c);
void print_counts_header(std::FILE* out, int label_width);

// One fold of a k-fold cross-validation: the sizes of its parts and the counts on its test part
// of the thresholds trained on its train part.
struct FoldResult {
  std::size_t train_segments = 0, test_segments = 0;
  Counts test;
};

struct CrossValidation {
  SplitMode split = SplitMode::ByImage;
  std::uint64_t seed = 1;
  TrainClass target = TrainClass::Marking;  // the classes reported: the trained one(s)
  std::vector<FoldResult> folds;
};

// Mean and sample standard deviation (n - 1; 0 for fewer than two values).
struct MeanStd {
  double mean = 0, std = 0;
};
MeanStd mean_std(std::span<const double> values);

// {"folds": K, "split", "seed", "train_segments": [..], "test_segments": [..],
//  "<class>": {"precision": [..], "recall": [..], "f1": [..], "mean_precision", "mean_recall",
//              "std_precision", "std_recall", "pooled": class_json(sum over folds)}}
// with one "<class>" entry per trained class.
nlohmann::json cross_validation_json(const CrossValidation& cv);
// The per-fold table with mean, standard deviation and pooled rows.
void print_cross_validation(std::FILE* out, const CrossValidation& cv);

}  // namespace fieldlines::cli
