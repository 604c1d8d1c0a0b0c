// A tuning tool against the installed package through fieldlines::core: render a synthetic
// field (synth), detect on it (detect), label it from the ground truth as a project would
// (data), and score the default thresholds on it (train).
#include <cstdio>

#include "fieldlines/data/labelled_set.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/synth/synth.hpp"
#include "fieldlines/train/metrics.hpp"

int main() {
  const fieldlines::synth::SynthSample sample = fieldlines::synth::generate({}, 7, 0);
  fieldlines::LineDetector detector;
  std::vector<fieldlines::Segment> segments;
  detector.detect(sample.bgr, segments);
  fieldlines::LabelledSet set;
  for (fieldlines::Segment s : segments) {
    s.label = fieldlines::Label::Marking;  // scored as if every segment were a marking
    set.add("synthetic", s);
  }
  const fieldlines::Evaluation e = fieldlines::evaluate(set, fieldlines::Thresholds{});
  std::printf("consumer: %zu segments, %ld predicted markings\n", segments.size(), e.total.marking.tp);
  return segments.empty() ? 1 : 0;
}
