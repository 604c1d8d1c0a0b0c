#include "training_report.hpp"

namespace fieldlines::cli {

nlohmann::json class_json(const ClassCounts& c) {
  return {{"tp", c.tp}, {"fp", c.fp}, {"fn", c.fn}, {"precision", c.precision()}, {"recall", c.recall()}, {"f1", c.f1()}};
}

nlohmann::json counts_json(const Counts& c) {
  return {{"marking", class_json(c.marking)}, {"boundary", class_json(c.boundary)}};
}

void print_counts_header(std::FILE* out, int w) {
  std::fprintf(out, "%-*s  %-33s  %-33s\n", w, "", "marking", "boundary");
  std::fprintf(out, "%-*s  %5s %5s %5s %5s %5s %5s  %5s %5s %5s %5s %5s %5s\n", w, "", "TP", "FP", "FN", "P", "R",
               "F1", "TP", "FP", "FN", "P", "R", "F1");
}

void print_counts(std::FILE* out, const std::string& label, const Counts& c) {
  // Long labels (paths) get their own line so the columns stay aligned.
  if (label.size() > 20) std::fprintf(out, "%s\n%-20s", label.c_str(), "");
  else std::fprintf(out, "%-20s", label.c_str());
  for (const ClassCounts* k : {&c.marking, &c.boundary})
    std::fprintf(out, "  %5ld %5ld %5ld %5.3f %5.3f %5.3f", k->tp, k->fp, k->fn, k->precision(), k->recall(), k->f1());
  std::fprintf(out, "\n");
}

}  // namespace fieldlines::cli
