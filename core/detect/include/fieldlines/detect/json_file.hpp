#pragma once
// Private: parsing a JSON document with a user-facing error.
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

}  // namespace fieldlines
