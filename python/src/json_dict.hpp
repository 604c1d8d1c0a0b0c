#pragma once
// Thresholds as Python dicts: the thresholds file's JSON form (docs/training.md, "The thresholds file"),
// so a dict read with load_thresholds_file, changed and saved is the same file a robot loads.
// Conversion goes through Python's json module, which round-trips every double exactly.
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "fieldlines/detect/thresholds_file.hpp"

namespace fieldlines::python {

pybind11::object to_python(const nlohmann::json& j);
// Raises ValueError for what JSON cannot hold (NaN, inf, objects that are not dicts, lists,
// strings, numbers, bools or None); NumPy scalars and arrays are accepted as their values.
nlohmann::json from_python(const pybind11::handle& obj, const std::string& what);

pybind11::dict thresholds_dict(const ThresholdsFile& file);
// Validates like the file reader (format, version, ranges): ValueError naming the field.
ThresholdsFile thresholds_from_dict(const pybind11::handle& obj, const std::string& what);

}  // namespace fieldlines::python
