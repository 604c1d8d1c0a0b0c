#pragma once
// A labelling project: a folder of images plus one JSON project file holding the detector
// parameters used, the thresholds, and per image its segments (with features) and labels.
//
// File schema (version 1; paths are relative to the project file's folder):
//   { "format": "fieldlines-project", "version": 1,
//     "detector": { DetectorParams }, "gradient_mode": ..., "classes": { ... },   (as thresholds file)
//     "split": { "mode": "image" | "row", "train_fraction": 0.7, "seed": 1 },  (optional: the test
//              split of fieldlines/data/split_spec.hpp; absent fields take these, the CLI's, defaults)
//     "detector_choice": { ... },  (optional: how "detector" was chosen from the frames, the
//              record `fieldlines calibrate` writes in its provenance; absent when it was not)
//     "segment_columns": ["x0","y0","x1","y1","saliency","gx_r","gx_g","gx_b","gy_r","gy_g","gy_b","label"],
//     "images": [ { "path": "frames/0001.png", "detect_ms": 3.1,
//                   "segments": [[x0, y0, x1, y1, saliency, gx.., gy.., "marking"], ...],
//                   "proposals": ["marking", "unlabelled", ...] } ] }   (optional, one per segment)
// Saves are atomic and refuse to replace a file that is not a readable project of a version
// this build understands, so a damaged or newer file is never overwritten.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/data/split_spec.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

inline constexpr int kProjectVersion = 1;

struct ImageEntry {
  std::string path;               // relative to the project folder
  std::vector<Segment> segments;  // segment.label = the human label, Unlabelled by default
  double detect_ms = 0;           // time the detector took on this image
  // Machine-proposed labels, never counted as labels: empty, or one per segment (Unlabelled =
  // no proposal). Accepting one makes it the segment's label; re-detection drops them.
  std::vector<Label> proposals{};

  // The proposal for segment i (Unlabelled when there is none).
  Label proposal(std::size_t i) const { return i < proposals.size() ? proposals[i] : Label::Unlabelled; }
};

// How re-detected segments inherit the labels of the old ones.
struct ReattachParams {
  float max_angle_deg = 5;     // direction difference allowed (undirected lines)
  float max_distance_px = 3;   // mean distance of the new endpoints to the old line
  float min_overlap = 0.5f;    // overlap along the line / the shorter segment's length
};

struct ReattachStats {
  std::size_t labelled_before = 0;  // labelled old segments
  std::size_t kept = 0;             // of those, how many passed their label on
  std::size_t lost = 0;             // labelled_before - kept
  std::size_t labelled_after = 0;   // new segments that received a label
};

// Gives each new segment the label of the best-overlapping labelled old segment (angle and
// distance within limits); the others stay Unlabelled.
ReattachStats reattach_labels(std::span<const Segment> old_segments, std::span<Segment> new_segments,
                              const ReattachParams& params = {});

class Project {
 public:
  // Throws fieldlines::Error naming the file on unreadable, malformed, newer-version content.
  static Project load(const std::filesystem::path& file);
  // Atomic. Refuses (throws) to replace an existing file it cannot read as a project.
  void save(const std::filesystem::path& file) const;

  // The flat labelled view training and evaluation use: all labelled segments, image by image,
  // named by image path.
  LabelledSet labelled() const;
  std::size_t labelled_count() const;
  // Replaces an image's segments with a fresh detection, re-attaching its labels.
  ReattachStats replace_segments(std::size_t image, std::vector<Segment> detected,
                                 const ReattachParams& params = {});
  // The image's absolute path given the project file's location.
  static std::filesystem::path resolve(const std::filesystem::path& project_file, const std::string& image);

  DetectorParams detector;
  Thresholds thresholds;
  SplitSpec split;  // how the labelled segments divide into train and test
  // How `detector` was chosen from the project's frames (detector_provenance(), the contrasts
  // measured and what they chose): an object while `detector` is what was chosen, null once it
  // is set otherwise (the studio clears it then), so an exported file never claims a choice its
  // detector no longer is.
  nlohmann::json detector_choice;
  std::vector<ImageEntry> images;
};

// Labelled data for a project made from reference CSV rows (image paths as in the CSV). Rows
// are grouped by image (images in first-seen order, rows of one image in file order);
// unlabelled rows are kept as Unlabelled segments. Detector and thresholds are the defaults.
Project project_from_reference_rows(std::span<const ReferenceRow> rows);

// The inverse, for writing a project's labels as the reference CSV (write_reference_csv): one
// row per segment that carries a human label, images in project order, segments in their order
// within the image, image paths exactly as stored in the project (relative to its folder).
// Unlabelled segments are NOT exported: the reference format has exactly one True label column
// per row and cannot represent them. Nor are the project's detector parameters, thresholds,
// detect_ms, or images without labelled segments. For every labelled segment the round trip
// rows -> project_from_reference_rows -> reference_rows_from_project (and through the CSV file,
// whose floats are written to read back bit for bit) gives back equal endpoints, gradients,
// saliency, label and image.
std::vector<ReferenceRow> reference_rows_from_project(const Project& project);

}  // namespace fieldlines
