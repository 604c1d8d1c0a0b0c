#include "arrays.hpp"

#include <climits>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include <opencv2/core.hpp>

namespace py = pybind11;

namespace fieldlines::python {
namespace {

static_assert(std::is_trivially_copyable_v<Segment> && std::is_standard_layout_v<Segment>,
              "segments are copied to NumPy with memcpy");
static_assert(sizeof(Label) == 1, "the dtype's label field is int8");

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string strides_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.strides(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

}  // namespace

cv::Mat image_view(const py::array& image, const std::string& what) {
  const py::dtype dt = image.dtype();
  const char kind = dt.kind();
  const py::ssize_t item = dt.itemsize();
  if (kind != 'u' || (item != 1 && item != 2))
    throw py::value_error(what + ": unsupported dtype " + dtype_text(image) +
                          " (expected uint8 or uint16, as from an 8- or 16-bit camera or file)");
  // '=' native, '|' not applicable (1 byte); '<' or '>' only when it differs from native.
  const char order = dt.attr("byteorder").cast<std::string>()[0];
  if (order != '=' && order != '|')
    throw py::value_error(what + ": non-native byte order " + dtype_text(image) +
                          " (convert with image.astype(image.dtype.newbyteorder('=')))");
  if (image.ndim() != 2 && image.ndim() != 3)
    throw py::value_error(what + ": expected HxW (grey) or HxWxC (C = 3 for BGR, 4 for BGRA) dimensions, got shape " +
                          shape_text(image));
  const py::ssize_t rows = image.shape(0), cols = image.shape(1);
  const py::ssize_t channels = image.ndim() == 3 ? image.shape(2) : 1;
  if (image.size() == 0) throw py::value_error(what + ": empty image (shape " + shape_text(image) + ")");
  if (channels != 1 && channels != 3 && channels != 4)
    throw py::value_error(what + ": unsupported channel count " + std::to_string(channels) +
                          " (expected 1 grey, 3 BGR or 4 BGRA; shape " + shape_text(image) + ")");
  if (rows > INT_MAX || cols > INT_MAX)
    throw py::value_error(what + ": too large (shape " + shape_text(image) + ")");
  // Pixels must be packed; the row stride may be larger (a crop), as in a cv::Mat. An axis of
  // length 1 may have any stride (NumPy gives image[:, :, None] a stride of 0).
  const bool packed = (channels == 1 || image.strides(2) == item) &&
                      (cols == 1 || image.strides(1) == channels * item);
  const py::ssize_t row_step = rows == 1 ? cols * channels * item : image.strides(0);
  if (!packed || row_step < cols * channels * item || row_step % item != 0)
    throw py::value_error(what + ": unsupported memory layout (shape " + shape_text(image) + ", strides " +
                          strides_text(image) +
                          "): pixels must be packed with rows in order; pass numpy.ascontiguousarray(image)");
  const int type = CV_MAKETYPE(item == 1 ? CV_8U : CV_16U, static_cast<int>(channels));
  // The detector only reads it: the const_cast lets read-only arrays through.
  return cv::Mat(static_cast<int>(rows), static_cast<int>(cols), type, const_cast<void*>(image.data()),
                 static_cast<std::size_t>(row_step));
}

const py::dtype& segment_dtype() {
  static const py::dtype* dtype = [] {
    py::list names, formats, offsets;
    auto field = [&](const char* name, const char* format, std::size_t offset) {
      names.append(name);
      formats.append(format);
      offsets.append(offset);
    };
    field("x0", "f4", offsetof(Segment, x0));
    field("y0", "f4", offsetof(Segment, y0));
    field("x1", "f4", offsetof(Segment, x1));
    field("y1", "f4", offsetof(Segment, y1));
    field("saliency", "f4", offsetof(Segment, saliency));
    field("grad_x", "(3,)f4", offsetof(Segment, grad_x));
    field("grad_y", "(3,)f4", offsetof(Segment, grad_y));
    field("label", "i1", offsetof(Segment, label));
    py::dict spec;
    spec["names"] = names;
    spec["formats"] = formats;
    spec["offsets"] = offsets;
    spec["itemsize"] = sizeof(Segment);
    // Leaked on purpose: a static py::object would be released after the interpreter is gone.
    return new py::dtype(py::module_::import("numpy").attr("dtype")(spec));
  }();
  return *dtype;
}

py::array segments_to_array(std::span<const Segment> segments) {
  py::array out(segment_dtype(), py::array::ShapeContainer{static_cast<py::ssize_t>(segments.size())});
  if (segments.empty()) return out;
  auto* bytes = static_cast<unsigned char*>(out.mutable_data());
  std::memcpy(bytes, segments.data(), segments.size_bytes());
  // The struct's padding after `label` is indeterminate: zero it so equal segments have equal bytes.
  constexpr std::size_t used = offsetof(Segment, label) + sizeof(Label);
  for (std::size_t i = 0; i < segments.size(); ++i)
    std::memset(bytes + i * sizeof(Segment) + used, 0, sizeof(Segment) - used);
  return out;
}

std::vector<Segment> segments_from_array(const py::object& segments) {
  if (!py::isinstance<py::array>(segments))
    throw py::value_error("segments: expected a NumPy array of fieldlines.SEGMENT_DTYPE (what detect() returns), got " +
                          py::str(py::type::of(segments)).cast<std::string>());
  const auto a = py::reinterpret_borrow<py::array>(segments);
  if (!a.dtype().equal(segment_dtype()))
    throw py::value_error("segments: expected dtype fieldlines.SEGMENT_DTYPE (what detect() returns), got " +
                          dtype_text(a));
  if (a.ndim() != 1) throw py::value_error("segments: expected a 1-D array, got shape " + shape_text(a));
  std::vector<Segment> out(static_cast<std::size_t>(a.shape(0)));
  // A strided view (segs[::2]) is gathered row by row.
  const auto* base = static_cast<const unsigned char*>(a.data());
  for (std::size_t i = 0; i < out.size(); ++i)
    std::memcpy(&out[i], base + static_cast<py::ssize_t>(i) * a.strides(0), sizeof(Segment));
  return out;
}

py::array mat_to_array(const cv::Mat& image) {
  CV_Assert(image.depth() == CV_8U);
  std::vector<py::ssize_t> shape{image.rows, image.cols};
  if (image.channels() > 1) shape.push_back(image.channels());
  py::array_t<std::uint8_t> out(shape);
  const std::size_t row_bytes = static_cast<std::size_t>(image.cols) * image.elemSize();
  auto* dst = out.mutable_data();
  for (int y = 0; y < image.rows; ++y) std::memcpy(dst + y * row_bytes, image.ptr(y), row_bytes);
  return out;
}

}  // namespace fieldlines::python
