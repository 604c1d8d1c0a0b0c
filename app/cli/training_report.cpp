#include "app/cli/training_report.hpp"

#include <cmath>

namespace fieldlines::cli {
namespace {

// The classes a cross-validation reports: the trained one, or both.
std::vector<std::pair<const char*, ClassCounts Counts::*>> reported_classes(TrainClass target) {
  std::vector<std::pair<const char*, ClassCounts Counts::*>> out;
  if (target != TrainClass::Boundary) out.emplace_back("marking", &Counts::marking);
  if (target != TrainClass::Marking) out.emplace_back("boundary", &Counts::boundary);
  return out;
}

// One class across the folds: each fold's test figures, their mean and deviation, and the
// counts pooled over the folds (every row is tested exactly once).
struct ClassOverFolds {
  std::vector<double> precision, recall, f1;
  MeanStd p, r;
  ClassCounts pooled;
};

ClassOverFolds over_folds(const CrossValidation& cv, ClassCounts Counts::*member) {
  ClassOverFolds o;
  for (const FoldResult& f : cv.folds) {
    const ClassCounts& c = f.test.*member;
    o.precision.push_back(c.precision());
    o.recall.push_back(c.recall());
    o.f1.push_back(c.f1());
    o.pooled += c;
  }
  o.p = mean_std(o.precision);
  o.r = mean_std(o.recall);
  return o;
}

}  // namespace

nlohmann::json class_json(const ClassCounts& c) {
  const auto figure = [&](double v) { return c.empty() ? nlohmann::json(nullptr) : nlohmann::json(v); };
  return {{"tp", c.tp}, {"fp", c.fp}, {"fn", c.fn}, {"precision", figure(c.precision())},
          {"recall", figure(c.recall())}, {"f1", figure(c.f1())}};
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
  for (const ClassCounts* k : {&c.marking, &c.boundary}) {
    if (k->empty()) std::fprintf(out, "  %5ld %5ld %5ld %5s %5s %5s", k->tp, k->fp, k->fn, "n/a", "n/a", "n/a");
    else std::fprintf(out, "  %5ld %5ld %5ld %5.3f %5.3f %5.3f", k->tp, k->fp, k->fn, k->precision(), k->recall(), k->f1());
  }
  std::fprintf(out, "\n");
}

MeanStd mean_std(std::span<const double> values) {
  MeanStd r;
  if (values.empty()) return r;
  for (const double v : values) r.mean += v;
  r.mean /= static_cast<double>(values.size());
  if (values.size() < 2) return r;
  double ss = 0;
  for (const double v : values) ss += (v - r.mean) * (v - r.mean);
  r.std = std::sqrt(ss / static_cast<double>(values.size() - 1));
  return r;
}

nlohmann::json cross_validation_json(const CrossValidation& cv) {
  nlohmann::json j;
  j["folds"] = cv.folds.size();
  j["split"] = to_string(cv.split);
  j["seed"] = cv.seed;
  j["train_segments"] = nlohmann::json::array();
  j["test_segments"] = nlohmann::json::array();
  for (const FoldResult& f : cv.folds) {
    j["train_segments"].push_back(f.train_segments);
    j["test_segments"].push_back(f.test_segments);
  }
  for (const auto& [name, member] : reported_classes(cv.target)) {
    const ClassOverFolds o = over_folds(cv, member);
    j[name] = {{"precision", o.precision},   {"recall", o.recall},        {"f1", o.f1},
               {"mean_precision", o.p.mean}, {"mean_recall", o.r.mean},   {"std_precision", o.p.std},
               {"std_recall", o.r.std},      {"pooled", class_json(o.pooled)}};
  }
  return j;
}

void print_cross_validation(std::FILE* out, const CrossValidation& cv) {
  const auto classes = reported_classes(cv.target);
  std::fprintf(out, "cross-validation: %zu folds by %s, seed %llu; test part of each fold\n", cv.folds.size(),
               std::string(to_string(cv.split)).c_str(), static_cast<unsigned long long>(cv.seed));
  std::fprintf(out, "%-7s %8s %8s", "", "train", "test");
  for (const auto& c : classes) std::fprintf(out, "  %-8s %5s %5s", c.first, "P", "R");
  std::fprintf(out, "\n");
  for (std::size_t i = 0; i < cv.folds.size(); ++i) {
    const FoldResult& f = cv.folds[i];
    std::fprintf(out, "fold %-2zu %8zu %8zu", i + 1, f.train_segments, f.test_segments);
    for (const auto& c : classes)
      std::fprintf(out, "  %-8s %5.3f %5.3f", "", (f.test.*c.second).precision(), (f.test.*c.second).recall());
    std::fprintf(out, "\n");
  }
  const auto summary = [&](const char* label, auto pick) {
    std::fprintf(out, "%-7s %8s %8s", label, "", "");
    for (const auto& c : classes) {
      const auto [pv, rv] = pick(over_folds(cv, c.second));
      std::fprintf(out, "  %-8s %5.3f %5.3f", "", pv, rv);
    }
    std::fprintf(out, "\n");
  };
  summary("mean", [](const ClassOverFolds& o) { return std::pair{o.p.mean, o.r.mean}; });
  summary("std", [](const ClassOverFolds& o) { return std::pair{o.p.std, o.r.std}; });
  summary("pooled", [](const ClassOverFolds& o) { return std::pair{o.pooled.precision(), o.pooled.recall()}; });
}

}  // namespace fieldlines::cli
