#pragma once
// Text and JSON forms of evaluation counts shared by train, eval and sweep.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "fieldlines/metrics.hpp"

namespace fieldlines::cli {

// {"tp", "fp", "fn", "precision", "recall", "f1"}
nlohmann::json class_json(const ClassCounts& c);
// {"marking": {...}, "boundary": {...}}
nlohmann::json counts_json(const Counts& c);
// One aligned line: "<label> marking  TP FP FN P R F1 | boundary ..."
void print_counts(std::FILE* out, const std::string& label, const Counts& c);
void print_counts_header(std::FILE* out, int label_width);

}  // namespace fieldlines::cli
