#pragma once
// NumPy <-> fieldlines conversions for the Python module.
//
// Images: uint8 or uint16, HxW, HxWx1, HxWx3 (BGR) or HxWx4 (BGRA), the detector's inputs. A
// C-contiguous array, or a view whose rows are strided but whose pixels are packed (a crop such
// as image[10:200, 50:400]), is wrapped as a cv::Mat without a copy; every other layout (a
// channel-reversed or subsampled view, negative strides, a non-native byte order) raises
// ValueError naming the layout and the fix (numpy.ascontiguousarray).
//
// Segments: a 1-D structured array of segment_dtype(), whose fields and layout are exactly
// fieldlines::Segment's (x0, y0, x1, y1, saliency: float32; grad_x, grad_y: 3 x float32, R,G,B;
// label: int8 code), so a detection is copied out with one memcpy.
#include <span>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <pybind11/numpy.h>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::python {

// The cv::Mat viewing `image`'s memory (the caller keeps `image` alive while it is used).
// `what` names the argument in messages ("image", "images[3]").
cv::Mat image_view(const pybind11::array& image, const std::string& what);

// The structured dtype of a segment array (created once, never freed: it outlives the module).
const pybind11::dtype& segment_dtype();
pybind11::array segments_to_array(std::span<const Segment> segments);
// Accepts exactly segment_dtype() (structured assignment in NumPy is by position, so another
// layout with the same names would be read wrongly); any other array raises ValueError.
std::vector<Segment> segments_from_array(const pybind11::object& segments);

// A cv::Mat (8-bit, 1/3/4 channels) as a new HxW or HxWxC uint8 array.
pybind11::array mat_to_array(const cv::Mat& image);

}  // namespace fieldlines::python
