#include "json_dict.hpp"

#include "fieldlines/detect/error.hpp"

namespace py = pybind11;

namespace fieldlines::python {

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

nlohmann::json from_python(const py::handle& obj, const std::string& what) {
  // NumPy scalars and arrays (what a notebook computes thresholds with) become plain values.
  const py::cpp_function plain([what](py::object o) -> py::object {
    if (py::hasattr(o, "tolist")) return o.attr("tolist")();
    throw py::value_error(what + ": " + py::str(py::type::of(o)).cast<std::string>() + " is not JSON data");
  });
  std::string text;
  try {
    text = py::module_::import("json").attr("dumps")(obj, py::arg("allow_nan") = false, py::arg("default") = plain)
               .cast<std::string>();
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
    throw py::value_error(what + ": not JSON data (" + std::string(py::str(e.value())) + ")");
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw py::value_error(what + ": " + e.what());  // e.g. a number beyond double (1e999)
  }
}

py::dict thresholds_dict(const ThresholdsFile& file) { return to_python(to_json(file)); }

ThresholdsFile thresholds_from_dict(const py::handle& obj, const std::string& what) {
  if (!py::isinstance<py::dict>(obj))
    throw py::value_error(what + ": expected a dict in the thresholds file's form (see fieldlines.load_thresholds_file), got " +
                          py::str(py::type::of(obj)).cast<std::string>());
  try {
    return thresholds_file_from_json(from_python(obj, what), what);
  } catch (const Error& e) {
    throw py::value_error(e.what());
  }
}

}  // namespace fieldlines::python
