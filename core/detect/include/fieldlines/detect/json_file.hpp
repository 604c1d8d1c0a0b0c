#pragma once
// Reading our versioned JSON files (project, thresholds, synthetic ground truth): parsing with a
// user-facing error, and the one check of a file's type name and version that every reader runs
// before it trusts any other field.
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

// Throws Error "<where>: malformed JSON (<detail>)". Catches every JSON exception, not only
// parse errors: a number like 1e999 is an out_of_range one.
inline nlohmann::json parse_json_text(const std::string& text, const std::string& where) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(where + ": malformed JSON (" + e.what() + ")");
  }
}

// One file type: the field naming it, its value, and how messages call it. Readers accept
// versions 1..current, so files written by older builds keep loading.
struct JsonFileFormat {
  // What a newer file means for the user: a file we save back (a project) stays untouched; one
  // we only read (thresholds, ground truth) needs a newer fieldlines.
  enum class Newer { NotModified, UpdateFieldlines };

  const char* key;       // "format" ("schema" for the synthetic ground truth)
  const char* name;      // its value, e.g. "fieldlines-project"
  const char* title;     // completes "not a fieldlines ...", e.g. "project file"
  const char* noun;      // precedes "version N", e.g. "project"
  int current_version;   // the newest version this build reads, and the one it writes
  Newer newer;
};

// {key: name, "version": current}: what every writer of the format starts from.
inline nlohmann::json json_file_header(const JsonFileFormat& f) {
  return {{f.key, f.name}, {"version", f.current_version}};
}

// Returns the file's version; throws Error "<where>: ..." unless `j` is an object whose `key`
// is `name` and whose integer "version" is in 1..current.
inline int require_json_file_format(const nlohmann::json& j, const JsonFileFormat& f, const std::string& where) {
  const auto type = j.find(f.key);  // end() for a non-object too
  if (type == j.end() || *type != f.name)
    throw Error(where + ": not a fieldlines " + f.title + " (\"" + f.key + "\" must be \"" + f.name + "\")");
  const auto v = j.find("version");
  if (v == j.end() || !v->is_number_integer()) throw Error(where + ": missing integer \"version\"");
  const long long version = v->get<long long>();
  const std::string n = std::to_string(version), current = std::to_string(f.current_version);
  if (version > f.current_version) {
    if (f.newer == JsonFileFormat::Newer::NotModified)
      throw Error(where + ": " + f.noun + " version " + n + " was written by a newer fieldlines (this one reads up to " +
                  current + "); it will not be modified");
    throw Error(where + ": " + f.noun + " version " + n + " is newer than this fieldlines understands (" + current +
                "); update fieldlines");
  }
  if (version < 1) throw Error(where + ": invalid " + f.noun + " version " + n);
  return static_cast<int>(version);
}

// The field `key` of object `j` as a T; throws Error "<where>: missing field 'key'" or "...: field
// 'key' has the wrong type".
template <typename T>
T json_field(const nlohmann::json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw Error(where + ": missing field '" + key + "'");
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw Error(where + ": field '" + key + "' has the wrong type");
  }
}

// `v` unchanged; throws Error "<where>: field 'key' is not a finite number" for NaN or infinity.
inline double finite_field(double v, const char* key, const std::string& where) {
  if (!std::isfinite(v)) throw Error(where + ": field '" + key + "' is not a finite number");
  return v;
}

}  // namespace fieldlines
