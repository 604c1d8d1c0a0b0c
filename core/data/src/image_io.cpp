#include "fieldlines/data/image_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <string>
#include <system_error>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

namespace fs = std::filesystem;
using Bytes = std::span<const unsigned char>;

[[noreturn]] void fail(const fs::path& path, const std::string& reason) {
  throw Error(path.string() + ": " + reason);
}

std::uint32_t big_endian(Bytes b, std::size_t at, int n) {
  std::uint32_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | b[at + static_cast<std::size_t>(i)];
  return v;
}

std::uint32_t little_endian(Bytes b, std::size_t at, int n) {
  std::uint32_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | b[at + static_cast<std::size_t>(i)];
  return v;
}

std::optional<cv::Size> make_size(std::uint64_t w, std::uint64_t h) {
  // Sizes beyond int range are still "known": clamp so the pixel-limit check rejects them.
  constexpr std::uint64_t kMax = 1u << 30;
  return cv::Size(static_cast<int>(std::min(w, kMax)), static_cast<int>(std::min(h, kMax)));
}

std::optional<cv::Size> probe_png(Bytes b) {
  static constexpr std::array<unsigned char, 8> kSig{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() < 24 || !std::equal(kSig.begin(), kSig.end(), b.begin())) return std::nullopt;
  if (std::memcmp(b.data() + 12, "IHDR", 4) != 0) return std::nullopt;
  return make_size(big_endian(b, 16, 4), big_endian(b, 20, 4));
}

std::optional<cv::Size> probe_jpeg(Bytes b) {
  if (b.size() < 4 || b[0] != 0xFF || b[1] != 0xD8) return std::nullopt;
  std::size_t i = 2;
  while (i + 1 < b.size()) {
    if (b[i] != 0xFF) return std::nullopt;
    while (i < b.size() && b[i] == 0xFF) ++i;  // fill bytes
    if (i >= b.size()) return std::nullopt;
    const unsigned marker = b[i++];
    if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;  // no length
    if (i + 2 > b.size()) return std::nullopt;
    const std::size_t length = big_endian(b, i, 2);
    // SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC) carry the frame size.
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      if (i + 7 > b.size()) return std::nullopt;
      return make_size(big_endian(b, i + 5, 2), big_endian(b, i + 3, 2));
    }
    if (length < 2) return std::nullopt;
    i += length;
  }
  return std::nullopt;
}

// libjpeg decodes a truncated JPEG "successfully", filling the missing rows with grey, which
// would silently give the detector a false edge. Entropy-coded data never holds FF D9, so a
// complete file has the end-of-image marker after its first start-of-scan (an EXIF thumbnail's
// own FF D9 comes before it; data some cameras append after the image comes after it).
bool jpeg_is_truncated(Bytes b) {
  if (b.size() < 4 || b[0] != 0xFF || b[1] != 0xD8) return false;
  std::size_t i = 2;
  while (i + 3 < b.size()) {
    if (b[i] != 0xFF) return false;  // not a marker: leave the verdict to the decoder
    const unsigned marker = b[i + 1];
    if (marker == 0xFF) {
      ++i;
      continue;
    }
    if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
      i += 2;
      continue;
    }
    const std::size_t length = big_endian(b, i + 2, 2);
    if (marker == 0xDA) {
      for (std::size_t k = i + 2 + length; k + 1 < b.size(); ++k)
        if (b[k] == 0xFF && b[k + 1] == 0xD9) return false;
      return true;
    }
    if (length < 2) return false;
    i += 2 + length;
  }
  return true;  // ended before any image data
}

std::optional<cv::Size> probe_bmp(Bytes b) {
  if (b.size() < 26 || b[0] != 'B' || b[1] != 'M') return std::nullopt;
  const std::uint32_t header = little_endian(b, 14, 4);
  if (header == 12) return make_size(little_endian(b, 18, 2), little_endian(b, 20, 2));
  const auto w = static_cast<std::int32_t>(little_endian(b, 18, 4));
  const auto h = static_cast<std::int32_t>(little_endian(b, 22, 4));  // negative: top-down rows
  return make_size(static_cast<std::uint64_t>(std::abs(static_cast<std::int64_t>(w))),
                   static_cast<std::uint64_t>(std::abs(static_cast<std::int64_t>(h))));
}

std::optional<cv::Size> probe_pnm(Bytes b) {
  if (b.size() < 3 || b[0] != 'P' || b[1] < '1' || b[1] > '6') return std::nullopt;
  std::size_t i = 2;
  std::uint64_t values[2] = {0, 0};
  for (auto& v : values) {
    for (;;) {  // whitespace and '#' comments
      if (i >= b.size()) return std::nullopt;
      if (b[i] == '#') {
        while (i < b.size() && b[i] != '\n') ++i;
      } else if (std::isspace(b[i])) {
        ++i;
      } else {
        break;
      }
    }
    if (!std::isdigit(b[i])) return std::nullopt;
    while (i < b.size() && std::isdigit(b[i]) && v < (1ull << 40)) v = v * 10 + (b[i++] - '0');
  }
  return make_size(values[0], values[1]);
}

std::optional<cv::Size> probe(Bytes b) {
  for (const auto f : {probe_png, probe_jpeg, probe_bmp, probe_pnm})
    if (const auto size = f(b)) return size;
  return std::nullopt;
}

// Reads the whole file (or its first `limit` bytes); errno names why it could not be opened.
std::vector<unsigned char> read_bytes(const fs::path& path, std::size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot be opened for reading (") + std::strerror(errno) + ")");
  std::vector<unsigned char> bytes;
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  bytes.resize(ec ? limit : std::min<std::size_t>(limit, size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (in.bad()) fail(path, "read error");
  return bytes;
}

}  // namespace

std::string describe_type(int cv_type) {
  const int depth = CV_MAT_DEPTH(cv_type);
  const int channels = CV_MAT_CN(cv_type);
  static constexpr const char* kDepth[] = {"8-bit unsigned", "8-bit signed", "16-bit unsigned",
                                           "16-bit signed", "32-bit integer", "32-bit float",
                                           "64-bit float", "16-bit float"};
  return std::string(kDepth[depth]) + " " + std::to_string(channels) + "-channel";
}

std::optional<cv::Size> probe_image_size(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  try {
    const auto head = read_bytes(path, 256 * 1024);  // enough for headers and most EXIF blocks
    return probe(head);
  } catch (const Error&) {
    return std::nullopt;
  }
}

cv::Mat load_image(const fs::path& path, const ImageLoadParams& params) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a folder, not an image file");
  if (!fs::is_regular_file(status)) fail(path, "not a regular file");
  const auto bytes = read_bytes(path, std::numeric_limits<std::size_t>::max());
  if (bytes.empty()) fail(path, "empty file (0 bytes)");

  auto check_pixels = [&](cv::Size size) {
    const auto pixels = static_cast<std::int64_t>(size.width) * size.height;
    if (pixels > params.max_pixels)
      fail(path, "image is " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                     " = " + std::to_string(pixels) + " pixels, more than the limit of " +
                     std::to_string(params.max_pixels));
  };
  // Checked before decoding, so a small file claiming a huge image never gets allocated.
  if (const auto header = probe(bytes)) {
    if (header->width == 0 || header->height == 0) fail(path, "image header says it is empty (0 pixels)");
    check_pixels(*header);
  }

  if (jpeg_is_truncated(bytes)) fail(path, "truncated JPEG (no end-of-image marker after the image data)");

  cv::Mat image;
  try {
    image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    fail(path, "could not be decoded (" + e.msg + ")");
  }
  if (image.empty())
    fail(path, "not a decodable image (corrupt, truncated or an unsupported format)");
  check_pixels(image.size());
  const int depth = image.depth();
  const int channels = image.channels();
  if ((depth != CV_8U && depth != CV_16U) || (channels != 1 && channels != 3 && channels != 4))
    fail(path, "unsupported pixel type " + describe_type(image.type()) +
                   " (expected 8- or 16-bit unsigned with 1, 3 or 4 channels)");
  return image;
}

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool has_image_extension(const fs::path& path) {
  static constexpr std::string_view kExtensions[] = {".png", ".jpg", ".jpeg", ".bmp", ".tif",
                                                     ".tiff", ".webp", ".ppm", ".pgm", ".pnm"};
  const std::string ext = lower_extension(path);
  return std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions);
}

std::vector<fs::path> list_images(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) fail(folder, "not a folder");
  std::vector<fs::path> images;
  fs::directory_iterator it(folder, ec);
  if (ec) fail(folder, "cannot list folder (" + ec.message() + ")");
  for (const auto& entry : it) {
    const auto name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (!entry.is_regular_file(ec) || !has_image_extension(entry.path())) continue;
    images.push_back(entry.path());
  }
  std::sort(images.begin(), images.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
  return images;
}

cv::Mat to_bgr8(const cv::Mat& image) {
  if (image.empty()) throw Error("to_bgr8: empty image");
  cv::Mat eight;
  if (image.depth() == CV_8U) eight = image;
  else if (image.depth() == CV_16U) image.convertTo(eight, CV_8U, 1.0 / 256.0);
  else throw Error("to_bgr8: unsupported pixel type " + describe_type(image.type()));
  cv::Mat bgr;
  switch (eight.channels()) {
    case 3: return eight;
    case 1: cv::cvtColor(eight, bgr, cv::COLOR_GRAY2BGR); return bgr;
    case 4: cv::cvtColor(eight, bgr, cv::COLOR_BGRA2BGR); return bgr;
    default: throw Error("to_bgr8: unsupported pixel type " + describe_type(image.type()));
  }
}

}  // namespace fieldlines
