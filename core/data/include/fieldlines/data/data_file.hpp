#pragma once
// A DATA file, as every command that reads labelled segments takes it: a labelling project file
// or a reference annotation CSV, read as one Project either way. Training and evaluation then
// work on its flat labelled view, Project::labelled() (a LabelledSet).
#include <filesystem>

#include "fieldlines/data/project.hpp"

namespace fieldlines {

// The format rule: a reference CSV when named *.csv (any case) or when it starts with the
// reference header, else a project file.
bool is_reference_csv_data(const std::filesystem::path& path);

// The whole file, unlabelled segments included. A CSV goes through project_from_reference_rows
// (default detector and thresholds, rows grouped by image), so a CSV and the project `convert`
// makes of it load the same. Throws fieldlines::Error naming the file (not a regular file,
// malformed rows, a damaged or newer project).
Project load_data_as_project(const std::filesystem::path& path);

}  // namespace fieldlines
