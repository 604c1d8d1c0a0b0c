#pragma once
// The DATA arguments of train/eval/sweep: each file is read as a Project
// (fieldlines/data/data_file.hpp); the command line adds only the name it was given.
#include <string>
#include <vector>

#include "fieldlines/data/data_file.hpp"
#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/data/project.hpp"

namespace fieldlines::cli {

struct LoadedData {
  std::string path;  // as given: provenance, table columns, merge prefixes
  Project project;   // a CSV's with the default detector and thresholds
};

// Throws fieldlines::Error naming the file on any problem (malformed rows included).
LoadedData load_labelled_data(const std::string& path);

// The labelled views of several files as one set; image names are prefixed with "<file>:" when
// there is more than one file, so equal names in different files stay different images.
LabelledSet merge(const std::vector<LoadedData>& data);

}  // namespace fieldlines::cli
