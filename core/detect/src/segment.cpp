#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

std::string_view to_string(Label label) {
  switch (label) {
    case Label::Marking: return "marking";
    case Label::Boundary: return "boundary";
    case Label::None: return "none";
    case Label::Unlabelled: break;
  }
  return "unlabelled";
}

bool parse_label(std::string_view text, Label& out) {
  for (const Label l : {Label::Marking, Label::Boundary, Label::None, Label::Unlabelled}) {
    if (text == to_string(l)) {
      out = l;
      return true;
    }
  }
  return false;
}

}  // namespace fieldlines
