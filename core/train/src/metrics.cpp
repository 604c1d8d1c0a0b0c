#include "fieldlines/train/metrics.hpp"

namespace fieldlines {
namespace {
double ratio(long a, long b) { return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : 0.0; }
}  // namespace

double ClassCounts::precision() const { return ratio(tp, tp + fp); }
double ClassCounts::recall() const { return ratio(tp, tp + fn); }
double ClassCounts::f1() const { return fbeta(1.0); }
double ClassCounts::fbeta(double beta) const {
  // Counts form avoids 0/0 when precision or recall is undefined.
  const double b2 = beta * beta;
  const double num = (1 + b2) * static_cast<double>(tp);
  const double den = num + b2 * static_cast<double>(fn) + static_cast<double>(fp);
  return den > 0 ? num / den : 0.0;
}

ClassCounts& ClassCounts::operator+=(const ClassCounts& o) {
  tp += o.tp, fp += o.fp, fn += o.fn;
  return *this;
}

Counts& Counts::operator+=(const Counts& o) {
  marking += o.marking, boundary += o.boundary;
  return *this;
}

void tally(Counts& c, Label truth, Label predicted) {
  if (truth == Label::Unlabelled) return;
  for (const Label cls : {Label::Marking, Label::Boundary}) {
    ClassCounts& cc = cls == Label::Marking ? c.marking : c.boundary;
    if (predicted == cls && truth == cls) ++cc.tp;
    else if (predicted == cls) ++cc.fp;
    else if (truth == cls) ++cc.fn;
  }
}

Evaluation evaluate(const LabelledSet& data, const Thresholds& thresholds) {
  Evaluation ev;
  ev.per_image.resize(data.images.size());
  for (std::size_t i = 0; i < data.images.size(); ++i) ev.per_image[i].image = data.images[i];
  for (std::size_t i = 0; i < data.size(); ++i) {
    const Segment& s = data.segments[i];
    tally(ev.per_image[data.image_of[i]].counts, s.label, classify(s, thresholds));
  }
  for (const ImageCounts& ic : ev.per_image) ev.total += ic.counts;
  return ev;
}

Counts count_labelled(std::span<const Segment> segments, const Thresholds& thresholds) {
  Counts counts;
  for (const Segment& s : segments) {
    if (s.label != Label::Unlabelled) tally(counts, s.label, classify(s, thresholds));
  }
  return counts;
}

}  // namespace fieldlines
