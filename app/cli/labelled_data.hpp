#pragma once
// Loading the DATA arguments of train/eval/sweep: each is a project file or a reference CSV.
#include <optional>
#include <string>
#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/data/labelled_set.hpp"

namespace fieldlines::cli {

struct LoadedData {
  std::string path;
  LabelledSet set;                        // image names as in the file
  std::optional<DetectorParams> detector; // from a project file
  std::optional<Thresholds> thresholds;   // from a project file
  std::size_t unlabelled = 0;             // segments skipped for having no label
};

// Throws fieldlines::Error naming the file on any problem (malformed rows included).
LoadedData load_labelled_data(const std::string& path);

// The DATA format rule of every command: a reference CSV when named *.csv (any case) or when it
// starts with the CSV header, else a project file.
bool is_reference_csv_data(const std::string& path);

// A whole DATA file as a project, unlabelled segments included (a CSV through
// project_from_reference_rows). Throws fieldlines::Error naming the file.
Project load_data_as_project(const std::string& path);

// Several files as one set; image names are prefixed with "<file>:" when there is more than
// one file, so equal names in different files stay different images.
LabelledSet merge(const std::vector<LoadedData>& data);

}  // namespace fieldlines::cli
