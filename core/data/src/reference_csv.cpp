#include "fieldlines/data/reference_csv.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "fieldlines/detect/atomic_file.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

constexpr std::array<const char*, 12> kFeatureColumns = {
    "img_path", "x0", "y0", "x1", "y1", "grad_Bx", "grad_Gx", "grad_Rx",
    "grad_By", "grad_Gy", "grad_Ry", "segment_length"};
constexpr std::array<const char*, 3> kLabelColumns = {"is_field_boundary", "is_field_marking",
                                                      "is_not_a_field_feature"};

// Splits one CSV line, honouring double quotes (image paths may contain commas).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else out.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

std::string quote_csv(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

float parse_float(const std::string& text, const std::string& where, const char* column) {
  float v = 0;
  const char* b = text.data();
  const char* e = b + text.size();
  while (b < e && *b == ' ') ++b;
  while (e > b && e[-1] == ' ') --e;
  const auto [ptr, ec] = std::from_chars(b, e, v);
  if (ec != std::errc() || ptr != e || b == e)
    throw Error(where + ": column '" + column + "': expected a number, got '" + text + "'");
  if (!std::isfinite(v))
    throw Error(where + ": column '" + column + "': value must be finite, got '" + text + "'");
  return v;
}

bool parse_bool(const std::string& text, const std::string& where, const char* column) {
  if (text == "True" || text == "true" || text == "TRUE" || text == "1") return true;
  if (text == "False" || text == "false" || text == "FALSE" || text == "0") return false;
  throw Error(where + ": column '" + column + "': expected True or False, got '" + text + "'");
}

std::string format_float(float v) {
  // %.9g round-trips every float exactly.
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  return buf;
}

}  // namespace

std::vector<ReferenceRow> read_reference_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open '" + path.string() + "'");
  const std::string name = path.string();
  std::string line;
  if (!std::getline(in, line)) throw Error(name + ":1: empty file, expected a CSV header");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // BOM
  const std::vector<std::string> header = split_csv(line);
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < header.size(); ++i) index[header[i]] = i;
  std::array<std::size_t, 12> col{};
  for (std::size_t i = 0; i < kFeatureColumns.size(); ++i) {
    const auto it = index.find(kFeatureColumns[i]);
    if (it == index.end())
      throw Error(name + ":1: header lacks the column '" + kFeatureColumns[i] + "'");
    col[i] = it->second;
  }
  int label_columns_found = 0;
  std::array<std::size_t, 3> label_col{};
  for (std::size_t i = 0; i < kLabelColumns.size(); ++i) {
    const auto it = index.find(kLabelColumns[i]);
    if (it != index.end()) label_col[i] = it->second, ++label_columns_found;
  }
  if (label_columns_found != 0 && label_columns_found != 3)
    throw Error(name + ":1: header has only some of the label columns " +
                "is_field_boundary,is_field_marking,is_not_a_field_feature");
  const bool labelled = label_columns_found == 3;

  std::vector<ReferenceRow> rows;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = name + ":" + std::to_string(line_no);
    const std::vector<std::string> f = split_csv(line);
    if (f.size() != header.size())
      throw Error(where + ": expected " + std::to_string(header.size()) + " columns, got " +
                  std::to_string(f.size()));
    ReferenceRow row;
    row.image = f[col[0]];
    float v[12];
    for (std::size_t i = 1; i < 12; ++i) v[i] = parse_float(f[col[i]], where, kFeatureColumns[i]);
    Segment& s = row.segment;
    s.x0 = v[1], s.y0 = v[2], s.x1 = v[3], s.y1 = v[4];
    s.grad_x = {v[7], v[6], v[5]};     // B,G,R -> R,G,B
    s.grad_y = {-v[10], -v[9], -v[8]}; // row above minus below -> image-down
    s.saliency = v[11];
    s.label = Label::Unlabelled;
    if (labelled) {
      const bool b = parse_bool(f[label_col[0]], where, kLabelColumns[0]);
      const bool m = parse_bool(f[label_col[1]], where, kLabelColumns[1]);
      const bool n = parse_bool(f[label_col[2]], where, kLabelColumns[2]);
      if (int(b) + int(m) + int(n) > 1) throw Error(where + ": several label columns are True");
      s.label = b ? Label::Boundary : m ? Label::Marking : n ? Label::None : Label::Unlabelled;
    }
    rows.push_back(std::move(row));
  }
  if (in.bad()) throw Error("cannot read '" + name + "'");
  return rows;
}

void write_reference_csv(const std::filesystem::path& path, std::span<const ReferenceRow> rows) {
  std::string out;
  for (const char* c : kFeatureColumns) out += std::string(c) + ",";
  out += "is_field_boundary,is_field_marking,is_not_a_field_feature\n";
  const auto yes = [](bool b) { return b ? "True" : "False"; };
  for (const ReferenceRow& r : rows) {
    const Segment& s = r.segment;
    const float v[11] = {s.x0, s.y0, s.x1, s.y1, s.grad_x[2], s.grad_x[1], s.grad_x[0],
                         -s.grad_y[2], -s.grad_y[1], -s.grad_y[0], s.saliency};
    out += quote_csv(r.image);
    for (const float x : v) {
      out += ',';
      out += format_float(x);
    }
    for (const Label l : {Label::Boundary, Label::Marking, Label::None}) {
      out += ',';
      out += yes(s.label == l);
    }
    out += '\n';
  }
  write_file_atomically(path, out);
}

bool looks_like_reference_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line)) return false;
  return line.find("img_path") != std::string::npos && line.find("segment_length") != std::string::npos;
}

}  // namespace fieldlines
