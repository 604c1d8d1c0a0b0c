#include "fieldlines/detect/segment.hpp"

#include "fieldlines/detect/enum_names.hpp"

namespace fieldlines {

// Namespace-scope constexpr: internal linkage.
constexpr EnumNames<Label, 4> kNames{{{{Label::Marking, "marking"},
                                       {Label::Boundary, "boundary"},
                                       {Label::None, "none"},
                                       {Label::Unlabelled, "unlabelled"}}}};

std::string_view to_string(Label label) { return kNames.name(label); }
bool parse_label(std::string_view text, Label& out) { return kNames.parse(text, out); }

}  // namespace fieldlines
