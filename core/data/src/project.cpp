#include "fieldlines/data/project.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"
#include "fieldlines/detect/json_file.hpp"
#include "fieldlines/detect/params_json.hpp"

namespace fieldlines {
namespace {

using nlohmann::json;

constexpr JsonFileFormat kFormat{"format", "fieldlines-project", "project file", "project", kProjectVersion,
                                 JsonFileFormat::Newer::NotModified};

const std::vector<std::string> kColumns = {"x0",   "y0",   "x1",   "y1",   "saliency", "gx_r",
                                           "gx_g", "gx_b", "gy_r", "gy_g", "gy_b",     "label"};

json segment_to_json(const Segment& s) {
  return json::array({s.x0, s.y0, s.x1, s.y1, s.saliency, s.grad_x[0], s.grad_x[1], s.grad_x[2], s.grad_y[0],
                      s.grad_y[1], s.grad_y[2], std::string(to_string(s.label))});
}

Segment segment_from_json(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != kColumns.size())
    throw Error(where + ": expected an array of " + std::to_string(kColumns.size()) + " values");
  float v[11];
  for (std::size_t i = 0; i < 11; ++i) {
    if (!j[i].is_number()) throw Error(where + ": '" + kColumns[i] + "' must be a number");
    v[i] = j[i].get<float>();
    if (!std::isfinite(v[i])) throw Error(where + ": '" + kColumns[i] + "' must be finite");
  }
  Segment s{v[0], v[1], v[2], v[3], v[4], {v[5], v[6], v[7]}, {v[8], v[9], v[10]}, Label::Unlabelled};
  if (!j[11].is_string() || !parse_label(j[11].get<std::string>(), s.label))
    throw Error(where + ": 'label' must be one of marking, boundary, none, unlabelled");
  return s;
}

// Parses the text as a project; throws with `where` in the message.
Project parse_project(const std::string& text, const std::string& where) {
  const json j = parse_json_text(text, where + ": damaged project file");
  require_json_file_format(j, kFormat, where);
  Project p;
  if (!j.contains("detector")) throw Error(where + ": missing field 'detector'");
  p.detector = detector_params_from_json(j["detector"], where + ": detector");
  p.thresholds = thresholds_from_json(j, where);
  if (j.contains("split")) p.split = split_spec_from_json(j["split"], where + ": split");
  if (j.contains("detector_choice")) {
    if (!j["detector_choice"].is_object()) throw Error(where + ": 'detector_choice' must be an object");
    p.detector_choice = j["detector_choice"];
  }
  if (!j.contains("segment_columns") || j["segment_columns"] != json(kColumns))
    throw Error(where + ": 'segment_columns' must be " + json(kColumns).dump());
  if (!j.contains("images") || !j["images"].is_array()) throw Error(where + ": missing array 'images'");
  for (std::size_t i = 0; i < j["images"].size(); ++i) {
    const json& im = j["images"][i];
    const std::string w = where + ": images[" + std::to_string(i) + "]";
    if (!im.is_object() || !im.contains("path") || !im["path"].is_string())
      throw Error(w + ": expected an object with a string 'path'");
    ImageEntry e;
    e.path = im["path"].get<std::string>();
    if (im.contains("detect_ms")) {
      if (!im["detect_ms"].is_number()) throw Error(w + ".detect_ms: expected a number");
      e.detect_ms = im["detect_ms"].get<double>();
    }
    if (!im.contains("segments") || !im["segments"].is_array()) throw Error(w + ": missing array 'segments'");
    for (std::size_t k = 0; k < im["segments"].size(); ++k)
      e.segments.push_back(segment_from_json(im["segments"][k], w + ".segments[" + std::to_string(k) + "]"));
    if (im.contains("proposals")) {
      const json& props = im["proposals"];
      if (!props.is_array() || props.size() != e.segments.size())
        throw Error(w + ".proposals: expected an array with one label per segment");
      for (std::size_t k = 0; k < props.size(); ++k) {
        Label l = Label::Unlabelled;
        if (!props[k].is_string() || !parse_label(props[k].get<std::string>(), l))
          throw Error(w + ".proposals[" + std::to_string(k) + "]: must be one of marking, boundary, none, unlabelled");
        e.proposals.push_back(l);
      }
    }
    p.images.push_back(std::move(e));
  }
  return p;
}

float angle_between_lines_deg(const Segment& a, const Segment& b) {
  const float t1 = std::atan2(a.y1 - a.y0, a.x1 - a.x0), t2 = std::atan2(b.y1 - b.y0, b.x1 - b.x0);
  float d = std::fmod(std::abs(t1 - t2), std::numbers::pi_v<float>);
  if (d > std::numbers::pi_v<float> / 2) d = std::numbers::pi_v<float> - d;
  return d * 180.f / std::numbers::pi_v<float>;
}

// Overlap of `b` with `a`'s line as a fraction of the shorter segment, or -1 when the two do not
// lie on the same line within the limits.
float overlap(const Segment& a, const Segment& b, const ReattachParams& p) {
  const float dx = a.x1 - a.x0, dy = a.y1 - a.y0;
  const float la = std::hypot(dx, dy), lb = std::hypot(b.x1 - b.x0, b.y1 - b.y0);
  if (la <= 0 || lb <= 0) return -1;
  if (angle_between_lines_deg(a, b) > p.max_angle_deg) return -1;
  const float ux = dx / la, uy = dy / la;
  const auto along = [&](float x, float y) { return (x - a.x0) * ux + (y - a.y0) * uy; };
  const auto across = [&](float x, float y) { return std::abs((x - a.x0) * uy - (y - a.y0) * ux); };
  if (0.5f * (across(b.x0, b.y0) + across(b.x1, b.y1)) > p.max_distance_px) return -1;
  const float s0 = along(b.x0, b.y0), s1 = along(b.x1, b.y1);
  const float inter = std::min(la, std::max(s0, s1)) - std::max(0.f, std::min(s0, s1));
  const float f = inter / std::min(la, lb);
  return f >= p.min_overlap ? f : -1;
}

}  // namespace

ReattachStats reattach_labels(std::span<const Segment> old_segments, std::span<Segment> new_segments,
                              const ReattachParams& params) {
  ReattachStats st;
  std::vector<char> used(old_segments.size(), 0);
  for (const Segment& o : old_segments) st.labelled_before += o.label != Label::Unlabelled;
  for (Segment& n : new_segments) {
    n.label = Label::Unlabelled;
    float best = -1;
    std::size_t arg = 0;
    for (std::size_t i = 0; i < old_segments.size(); ++i) {
      if (old_segments[i].label == Label::Unlabelled) continue;
      const float f = overlap(old_segments[i], n, params);
      if (f > best) best = f, arg = i;
    }
    if (best >= 0) {
      n.label = old_segments[arg].label;
      used[arg] = 1;
      ++st.labelled_after;
    }
  }
  for (std::size_t i = 0; i < old_segments.size(); ++i)
    st.kept += old_segments[i].label != Label::Unlabelled && used[i];
  st.lost = st.labelled_before - st.kept;
  return st;
}

Project Project::load(const std::filesystem::path& file) { return parse_project(read_file(file), file.string()); }

void Project::save(const std::filesystem::path& file) const {
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) {
    // Never replace what we cannot read: it may be a newer version or hand-repairable.
    try {
      parse_project(read_file(file), file.string());
    } catch (const Error& e) {
      throw Error(std::string("refusing to overwrite: ") + e.what());
    }
  }
  json j = json_file_header(kFormat);
  j["detector"] = detector_params_to_json(detector);
  j.update(thresholds_to_json(thresholds));
  j["split"] = split_spec_to_json(split);
  if (detector_choice.is_object()) j["detector_choice"] = detector_choice;
  j["segment_columns"] = kColumns;
  json images_json = json::array();
  for (const ImageEntry& e : images) {
    json segs = json::array();
    for (const Segment& s : e.segments) segs.push_back(segment_to_json(s));
    json image = {{"path", e.path}, {"detect_ms", e.detect_ms}, {"segments", std::move(segs)}};
    if (!e.proposals.empty()) {
      json props = json::array();
      for (std::size_t k = 0; k < e.segments.size(); ++k) props.push_back(std::string(to_string(e.proposal(k))));
      image["proposals"] = std::move(props);
    }
    images_json.push_back(std::move(image));
  }
  j["images"] = std::move(images_json);
  write_file_atomically(file, j.dump(1) + "\n");
}

LabelledSet Project::labelled() const {
  LabelledSet out;
  for (const ImageEntry& e : images)
    for (const Segment& s : e.segments) out.add(e.path, s);
  return out;
}

std::size_t Project::labelled_count() const {
  std::size_t n = 0;
  for (const ImageEntry& e : images)
    for (const Segment& s : e.segments) n += s.label != Label::Unlabelled;
  return n;
}

ReattachStats Project::replace_segments(std::size_t image, std::vector<Segment> detected,
                                        const ReattachParams& params) {
  if (image >= images.size()) throw Error("image index " + std::to_string(image) + " out of range");
  ImageEntry& e = images[image];
  const ReattachStats st = reattach_labels(e.segments, detected, params);
  e.segments = std::move(detected);
  e.proposals.clear();  // they were for the old segments
  return st;
}

std::filesystem::path Project::resolve(const std::filesystem::path& project_file, const std::string& image) {
  const std::filesystem::path p(image);
  return p.is_absolute() ? p : project_file.parent_path() / p;
}

Project project_from_reference_rows(std::span<const ReferenceRow> rows) {
  Project p;
  std::map<std::string, std::size_t> index;
  for (const ReferenceRow& r : rows) {
    const auto [it, added] = index.try_emplace(r.image, p.images.size());
    if (added) p.images.push_back({r.image, {}, 0});
    p.images[it->second].segments.push_back(r.segment);
  }
  return p;
}

std::vector<ReferenceRow> reference_rows_from_project(const Project& project) {
  std::vector<ReferenceRow> rows;
  rows.reserve(project.labelled_count());
  for (const ImageEntry& e : project.images)
    for (const Segment& s : e.segments)
      if (s.label != Label::Unlabelled) rows.push_back({e.path, s});
  return rows;
}

}  // namespace fieldlines
