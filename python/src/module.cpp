// `import fieldlines`: the line detector, the classifier, the thresholds file and label-free
// calibration, in the style of OpenCV's Python bindings (docs/python.md).
//
// Errors: fieldlines::Error (bad input, bad values, malformed files) becomes ValueError; a file
// that cannot be opened or written becomes OSError (FileNotFoundError, PermissionError, ...).
// Threads: detect() and calibrate() release the GIL. A LineDetector owns reused buffers, so its
// calls are serialised by its own mutex (one detector per thread runs in parallel). The mutex
// is only ever waited for with the GIL released, so holding it and taking the GIL cannot
// deadlock.
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/detect/camera_file.hpp"
#include "fieldlines/detect/ground_features_json.hpp"
#include "fieldlines/detect/steady_features.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/thresholds_file.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/calibration_inputs.hpp"
#include "fieldlines/train/detector_calibration.hpp"
#include "fieldlines/train/stripe_width.hpp"
#include "json_dict.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace fieldlines::python {
namespace {

// OSError (with its errno subclass) when `path` cannot be opened for reading; fieldlines' own
// readers only say "cannot read", which is not enough to tell a missing file from a bad one.
void require_readable(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    errno = EISDIR;
    PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
    throw py::error_already_set();
  }
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
    throw py::error_already_set();
  }
  std::fclose(f);
}

ThresholdsFile load_file(const fs::path& path) {
  require_readable(path);
  return load_thresholds_file(path);  // malformed content: Error -> ValueError
}

void save_file(const fs::path& path, const py::handle& thresholds) {
  const ThresholdsFile file = thresholds_from_dict(thresholds, "thresholds");
  try {
    save_thresholds_file(path, file);
  } catch (const Error& e) {
    PyErr_SetString(PyExc_OSError, e.what());
    throw py::error_already_set();
  }
}

// None: the authors' defaults (ThresholdsFile{}).
ThresholdsFile config_or_defaults(const py::object& thresholds) {
  if (thresholds.is_none()) return {};
  return thresholds_from_dict(thresholds, "thresholds");
}

std::unique_lock<std::mutex> lock_without_gil(std::mutex& m) {
  py::gil_scoped_release nogil;
  return std::unique_lock<std::mutex>(m);
}

class Detector {
 public:
  explicit Detector(ThresholdsFile config)
      : config_(std::move(config)), detector_(config_.detector, config_.thresholds) {
    find_boundary_with_features();
  }

  // The field features of the last detect(), as `fieldlines detect --json` writes them.
  py::dict features() {
    const auto lock = lock_without_gil(mutex_);
    const FieldFeatures& f = detector_.features();
    py::list markings, intersections, ellipses, boundary;
    for (const Marking& m : f.markings)
      markings.append(py::dict(py::arg("x0") = m.x0, py::arg("y0") = m.y0, py::arg("x1") = m.x1, py::arg("y1") = m.y1,
                               py::arg("width") = m.width));
    for (const Intersection& j : f.intersections) {
      py::list rays;
      for (int k = 0; k < j.num_rays && k < 4; ++k) rays.append(j.heading_rays[static_cast<std::size_t>(k)]);
      intersections.append(py::dict(py::arg("x") = j.x, py::arg("y") = j.y, py::arg("type") = to_string(j.type),
                                    py::arg("num_rays") = j.num_rays, py::arg("heading_rays") = rays,
                                    py::arg("confidence") = j.confidence));
    }
    for (const MarkingEllipse& e : f.ellipses)
      ellipses.append(py::dict(py::arg("cx") = e.cx, py::arg("cy") = e.cy, py::arg("width") = e.width,
                               py::arg("height") = e.height, py::arg("angle_deg") = e.angle_deg,
                               py::arg("confidence") = e.confidence));
    for (const FieldBoundary::Point& p : f.field_boundary.points) boundary.append(py::make_tuple(p.x, p.y));
    return py::dict(py::arg("markings") = markings, py::arg("intersections") = intersections,
                    py::arg("ellipses") = ellipses, py::arg("field_boundary") = boundary);
  }

  // The features of the last detect() on the ground, as `fieldlines detect --json` writes an
  // image's "ground" (ground_features_json.hpp); None without a camera.
  py::object ground_features() {
    const auto lock = lock_without_gil(mutex_);
    if (!camera_) return py::none();
    return to_python(nlohmann::json(to_json(detector_.ground_features())));
  }

  // The last detect()'s ground features through `steady` (SteadyFeatures::update).
  py::dict steady_update(SteadyFeatures& steady, double time_ms, const GroundMotion& motion) {
    const auto lock = lock_without_gil(mutex_);
    if (!camera_) throw Error("steady features need the detector's camera (set LineDetector.camera first)");
    return to_python(nlohmann::json(to_json(steady.update(detector_.ground_features(), time_ms, motion))));
  }

  py::array detect(const py::array& image) {
    const cv::Mat view = image_view(image, "image");  // no copy; `image` outlives the call
    std::unique_lock<std::mutex> lock;
    {
      py::gil_scoped_release nogil;
      lock = std::unique_lock<std::mutex>(mutex_);
      detector_.detect(view, segments_);
    }
    return segments_to_array(segments_);
  }

  // python/bench.py's reference: the same detect() timed in C++, without Python around it.
  std::vector<double> time_detect(const py::array& image, int repeat) {
    const cv::Mat view = image_view(image, "image");
    std::vector<double> ms;
    py::gil_scoped_release nogil;
    const std::lock_guard<std::mutex> lock(mutex_);
    for (int i = 0; i < repeat; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      detector_.detect(view, segments_);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return ms;
  }

  py::dict thresholds() {
    const auto lock = lock_without_gil(mutex_);
    return thresholds_dict(config_);
  }

  void set_thresholds(const py::handle& thresholds) {
    ThresholdsFile config = thresholds_from_dict(thresholds, "thresholds");
    const auto lock = lock_without_gil(mutex_);
    if (config.detector == config_.detector) {
      detector_.set_thresholds(config.thresholds);  // keeps the warm buffers
    } else {
      detector_ = LineDetector(config.detector, config.thresholds);
    }
    config_ = std::move(config);
    find_boundary_with_features();
    detector_.set_camera(camera_);  // a new detector starts with none
  }

  // The camera file's form without its header: {fx, fy, cx, cy, pitch_deg, roll_deg, height_m}.
  py::object camera() {
    const auto lock = lock_without_gil(mutex_);
    return camera_ ? to_python(camera_json_) : py::none();
  }

  void set_camera(const py::handle& camera) {
    std::optional<GroundCamera> parsed;
    nlohmann::json given;
    if (!camera.is_none()) {
      given = from_python(camera, "camera");
      if (!given.is_object()) throw Error("camera: expected a dict or None");
      nlohmann::json j = given;
      const nlohmann::json header = to_json(GroundCamera{});  // the camera file's format and version
      for (const char* key : {"format", "version"})
        if (!j.contains(key)) j[key] = header[key];
      parsed = ground_camera_from_json(j, "camera");
    }
    const auto lock = lock_without_gil(mutex_);
    detector_.set_camera(parsed);
    camera_ = parsed;
    camera_json_ = std::move(given);  // returned as given: degrees stay the user's digits
  }

 private:
  // features() reports the boundary whenever a feature stage is on, as detect --json does.
  void find_boundary_with_features() {
    const DetectorParams& p = config_.detector;
    detector_.set_find_field_boundary(p.stripes || p.intersections || p.centre_circle);
  }

  std::mutex mutex_;
  ThresholdsFile config_;
  std::optional<GroundCamera> camera_;
  nlohmann::json camera_json_;  // the dict it was given
  LineDetector detector_;
  std::vector<Segment> segments_;  // reused: its capacity stays between calls
};

py::tuple labels() {
  // Indexed by the int code of fieldlines::Label (0 none, 1 boundary, 2 marking).
  py::tuple names(3);
  for (const Label l : {Label::None, Label::Boundary, Label::Marking})
    names[static_cast<std::size_t>(l)] = py::str(std::string(to_string(l)));
  return names;
}

py::array classify_segments(const py::object& segments, const py::object& thresholds) {
  const Thresholds t = config_or_defaults(thresholds).thresholds;
  const std::vector<Segment> in = segments_from_array(segments);
  py::array_t<std::int8_t> out(static_cast<py::ssize_t>(in.size()));
  auto* labels = out.mutable_data();
  for (std::size_t i = 0; i < in.size(); ++i) labels[i] = static_cast<std::int8_t>(classify(in[i], t));
  return out;
}

py::dict calibrate_images(const py::object& images, const py::object& thresholds, bool keep_detector) {
  if (py::isinstance<py::array>(images))
    throw py::type_error("images: expected a sequence of images, got one array (pass [image])");
  if (!py::isinstance<py::iterable>(images))
    throw py::type_error("images: expected a sequence of images (list of NumPy arrays)");
  const ThresholdsFile start = config_or_defaults(thresholds);
  // Every image is checked (and kept alive) before the GIL is released.
  std::vector<py::array> arrays;
  std::vector<cv::Mat> views;
  for (const py::handle item : images) {
    const std::string what = "images[" + std::to_string(arrays.size()) + "]";
    if (!py::isinstance<py::array>(item))
      throw py::type_error(what + ": expected a NumPy array, got " + py::str(py::type::of(item)).cast<std::string>());
    arrays.push_back(py::reinterpret_borrow<py::array>(item));
    views.push_back(image_view(arrays.back(), what));
  }
  Calibration fit;
  Thresholds calibrated;
  CalibrationInputs inputs;
  Thresholds adapted;
  DetectorParams chosen = start.detector;
  nlohmann::json detector_report = {{"calibrated", false}};
  {
    py::gil_scoped_release nogil;
    // The venue's detector from a first look at the frames, as `fieldlines calibrate` does.
    if (!keep_detector) {
      FieldContrast contrast({}, start.detector);
      for (const cv::Mat& view : views) contrast.add_image(view);
      chosen = calibrated_detector(start.detector, contrast);
      detector_report = detector_provenance(contrast, chosen);
    }
    LineDetector detector(for_fitting(chosen), start.thresholds);
    inputs.check_stripes(chosen);
    for (const cv::Mat& view : views) inputs.add_image(detector, view);
    adapted = inputs.image_settings(start.thresholds, true);
    fit = calibrate(inputs.segments(), adapted, {}, inputs.boundary_candidates(), inputs.marking_candidates());
    keep_given_markings(fit, adapted, inputs.frames_with_field());
  }
  try {
    calibrated = calibrated_thresholds(fit, adapted);
  } catch (const Error& e) {
    throw py::value_error(std::string("calibration refused: ") + e.what());
  }
  calibrate_stripe_width(chosen, detector_report, inputs, calibrated);
  ThresholdsFile file;
  file.detector = chosen;
  file.thresholds = calibrated;
  nlohmann::json& p = file.provenance;
  p = calibration_provenance(fit);
  p["inputs"] = "python: fieldlines.calibrate";
  p["detector"] = detector_report;
  p["counts"] = {{"segments", inputs.segments().size()}, {"images", views.size()},
                 {"frames_with_field_colour", inputs.frames_with_field()}};
  p["fieldlines_version"] = FIELDLINES_VERSION;
  return thresholds_dict(file);
}

py::array imread(const fs::path& path) {
  require_readable(path);
  return mat_to_array(to_bgr8(load_image(path)));
}

}  // namespace
}  // namespace fieldlines::python

PYBIND11_MODULE(fieldlines, m) {
  using namespace fieldlines;
  using namespace fieldlines::python;
  m.doc() = "Soccer-field line detection (ELSED + colour transitions) for robots.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.attr("__version__") = FIELDLINES_VERSION;
  m.attr("LABELS") = labels();
  m.attr("LABEL_NONE") = static_cast<int>(Label::None);
  m.attr("LABEL_BOUNDARY") = static_cast<int>(Label::Boundary);
  m.attr("LABEL_MARKING") = static_cast<int>(Label::Marking);
  m.attr("SEGMENT_DTYPE") = segment_dtype();

  py::class_<Detector>(m, "LineDetector", R"(ELSED line segments with colour gradients, classified.

LineDetector(thresholds=None): the authors' defaults, or a thresholds dict (the thresholds
file's form, e.g. from load_thresholds_file or calibrate). Keep one per thread: it reuses its
buffers between calls.)")
      .def(py::init([](const py::object& thresholds) {
             return new Detector(config_or_defaults(thresholds));
           }),
           py::arg("thresholds") = py::none())
      .def_static("from_thresholds_file", [](const fs::path& path) { return new Detector(load_file(path)); },
                  py::arg("path"), "A detector with the parameters and thresholds of a thresholds file.")
      .def("detect", &Detector::detect, py::arg("image"),
           R"(Segments of an image: uint8 (or uint16) HxWx3 BGR, HxW grey or HxWx4 BGRA.

Returns a 1-D structured array of SEGMENT_DTYPE: x0, y0, x1, y1 (pixels), saliency (validated
pixels), grad_x, grad_y (3 x float32, R,G,B; grad_y image-down), label (int code into LABELS).
A C-contiguous image (or a crop of one) is read without a copy; the GIL is released meanwhile.)")
      .def("features", &Detector::features,
           R"(The field features of the last detect(), as `fieldlines detect --json` names them
(ros-sports soccer_vision_2d_msgs): {"markings": [{x0, y0, x1, y1, width}], "intersections":
[{x, y, type ("L", "T" or "X"), num_rays, heading_rays (radians ascending in [0, 2pi), 0 along
+x, pi/2 image down), confidence}], "ellipses": [{cx, cy, width, height, angle_deg, confidence}],
"field_boundary": [(x, y), ...]}. Each is empty unless its stage is on in the thresholds'
"detector" (stripes, intersections, centre_circle; the boundary with any of them).)")
      .def("ground_features", &Detector::ground_features,
           R"(The field features of the last detect() on the ground when a camera is set (None
otherwise), as `fieldlines detect --camera --json` writes an image's "ground", in ros-sports
soccer_vision_3d_msgs names: metres from the camera's foot (x ahead, y left, z up), {"segments":
[{start, end ({x, y, z}), width, start_covariance, end_covariance ([xx, xy, yy], m^2)}],
"intersections": [{center, center_covariance, type, num_rays, rays ([{x, y, z}] unit ground
directions), confidence}], "ellipses": [{center {position, orientation}, diameter,
center_covariance, confidence}], "field_boundary": {points, covariances}}. Points at or above
the horizon are never projected.)")
      .def_property("thresholds", &Detector::thresholds, &Detector::set_thresholds,
                    "The detector's thresholds file as a dict; assign a dict to change it.")
      .def_property("camera", &Detector::camera, &Detector::set_camera,
                    R"(The camera over the field, or None (the default): a dict {fx, fy, cx, cy (px),
pitch_deg (down from the horizontal), roll_deg, height_m (above the turf)}, as a camera file
holds it. With it, the centre circle is also fitted on the turf as a circle of the thresholds'
detector "centre_circle_radius", which finds one the frame shows a single arc of. Assign per
frame when the pose changes; a bad value raises ValueError and keeps the camera it had.)")
      .def("_time_detect", &Detector::time_detect, py::arg("image"), py::arg("repeat") = 1,
           "Milliseconds of each of `repeat` detect() calls timed in C++ (for python/bench.py).")
      .def("__repr__", [](Detector&) { return std::string("<fieldlines.LineDetector>"); });

  py::class_<SteadyFeatures>(m, "SteadyFeatures", R"(Junctions and the centre circle held steady on the ground over a stream.

A feature the detector misses for up to hold_ms is kept (its confidence fading with its age),
moved by the robot's motion since; seen again, its position is smoothed with its track
(smoothing: the new observation's weight). Keep one per camera; off by default on the robot.)")
      .def(py::init([](double hold_ms, double match_m, double circle_match_m, double smoothing) {
             return new SteadyFeatures({hold_ms, match_m, circle_match_m, smoothing});
           }),
           py::arg("hold_ms") = 80.0, py::arg("match_m") = 0.3, py::arg("circle_match_m") = 0.5,
           py::arg("smoothing") = 0.5)
      .def(
          "update",
          [](SteadyFeatures& self, Detector& detector, double time_ms, std::array<double, 3> motion) {
            return detector.steady_update(self, time_ms, {motion[0], motion[1], motion[2]});
          },
          py::arg("detector"), py::arg("time_ms"), py::arg("motion") = std::array<double, 3>{0, 0, 0},
          R"(The steady ground features after `detector`'s last detect() at time_ms, the robot having
moved by motion = (dx, dy, dyaw) (metres, radians; in the last frame's ground frame) since the
last call: the same dict as LineDetector.ground_features(). ValueError without a camera.)")
      .def("reset", &SteadyFeatures::reset, "Forget every track (a new stream).");

  m.def("load_thresholds_file", [](const fs::path& path) { return thresholds_dict(load_file(path)); },
        py::arg("path"), "A thresholds file as a dict (validated; OSError if unreadable, ValueError if malformed).");
  m.def("save_thresholds_file", &save_file, py::arg("path"), py::arg("thresholds"),
        "Validates the dict and writes it atomically (ValueError if invalid, OSError if unwritable).");
  m.def("classify", &classify_segments, py::arg("segments"), py::arg("thresholds") = py::none(),
        "Label codes (int8 array) of segments (SEGMENT_DTYPE) under a thresholds dict (default: the authors').");
  m.def("calibrate", &calibrate_images, py::arg("images"), py::arg("thresholds") = py::none(),
        py::arg("keep_detector") = false,
        R"(Label-free calibration: a thresholds dict from a list of images, no labels needed.

Chooses the detector parameters from the images' field (as fieldlines calibrate; with
keep_detector those of `thresholds`, default built-in), detects every image with them, then fits
both classes. Raises ValueError with the reason when the markings cannot
be fitted; a class the images do not show is disabled (provenance.fit says why).)");
  m.def("imread", &imread, py::arg("path"),
        "An image file as uint8 HxWx3 BGR (16-bit scaled, grey replicated, alpha dropped), decoded as the CLI does.");
  m.def("set_num_threads", [](int n) { cv::setNumThreads(n); }, py::arg("n"),
        "OpenCV's thread count for the filters (cv2.setNumThreads); fieldlines bench times with 1.");
  m.def("get_num_threads", [] { return cv::getNumThreads(); });
}
