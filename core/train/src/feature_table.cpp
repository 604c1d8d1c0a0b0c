#include "fieldlines/train/feature_table.hpp"

#include <cmath>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

FeatureTable::FeatureTable(std::span<const Segment> segments, const Thresholds& base,
                           const LabelledCandidates& candidates) {
  for (const auto& [flags, what] : {std::pair{candidates.marking, "marking"}, {candidates.boundary, "boundary"}})
    if (!flags.empty() && flags.size() != segments.size())
      throw Error(std::string(what) + " candidates: " + std::to_string(flags.size()) + " flags for " +
                  std::to_string(segments.size()) + " segments");
  const auto may = [](std::span<const std::uint8_t> flags, std::size_t i) { return flags.empty() || flags[i] != 0; };
  // A test that can never pass: no projection threshold is below -1e30.
  constexpr float kNever = -1e30f;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (s.label == Label::Unlabelled) continue;
    const SegmentFeatures f = compute_features(s, base);
    length.push_back(f.length);
    boundary_proj.push_back(may(candidates.boundary, i) ? f.boundary.projection : kNever);
    boundary_angle.push_back(f.boundary.angle_deg);
    for (int k = 0; k < 2; ++k) {
      // An absent second test, or a segment that may not be a marking, never passes.
      const bool present = k < f.marking_count && may(candidates.marking, i);
      marking_proj[k].push_back(present ? f.marking[k].projection : kNever);
      marking_angle[k].push_back(present ? f.marking[k].angle_deg : 1e30f);
    }
    truth.push_back(s.label);
    is_marking.push_back(s.label == Label::Marking);
    is_boundary.push_back(s.label == Label::Boundary);
    positives_marking += s.label == Label::Marking;
    positives_boundary += s.label == Label::Boundary;
  }
}

namespace {

// The scoring loop; kBoundary = false skips the boundary test (a boundary whose min length is
// +inf never passes), which is the hot case of training the marking class alone.
template <bool kBoundary>
void count_loop(const FeatureTable& f, const ClassThresholds& b, const ClassThresholds& m, std::int32_t& tpm,
                std::int32_t& npm, std::int32_t& tpb, std::int32_t& npb) {
  const std::size_t n = f.size();
  const float* len = f.length.data();
  const float *bp = f.boundary_proj.data(), *ba = f.boundary_angle.data();
  const float *mp0 = f.marking_proj[0].data(), *ma0 = f.marking_angle[0].data();
  const float *mp1 = f.marking_proj[1].data(), *ma1 = f.marking_angle[1].data();
  const std::int32_t *ism = f.is_marking.data(), *isb = f.is_boundary.data();
  const float bl = b.min_length, bpr = b.min_projection, ban = b.max_angle_deg;
  const float ml = m.min_length, mpr = m.min_projection, man = m.max_angle_deg;
  // 32-bit lanes, bitwise & / | and no branches: the compiler vectorises this loop.
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t pb = 0;
    if constexpr (kBoundary) pb = (len[i] >= bl) & (bp[i] >= bpr) & (ba[i] <= ban);
    const std::int32_t pm = (pb ^ 1) & (len[i] >= ml) &
                            (((mp0[i] >= mpr) & (ma0[i] <= man)) | ((mp1[i] >= mpr) & (ma1[i] <= man)));
    tpm += pm & ism[i];
    npm += pm;
    if constexpr (kBoundary) {
      tpb += pb & isb[i];
      npb += pb;
    }
  }
}

}  // namespace

Counts FeatureTable::count(const ClassThresholds& b, const ClassThresholds& m) const {
  std::int32_t tpm = 0, npm = 0, tpb = 0, npb = 0;
  if (std::isinf(b.min_length) && b.min_length > 0) count_loop<false>(*this, b, m, tpm, npm, tpb, npb);
  else count_loop<true>(*this, b, m, tpm, npm, tpb, npb);
  const long fpm = npm - tpm, fpb = npb - tpb;
  Counts c;
  c.marking = {tpm, fpm, positives_marking - tpm};
  c.boundary = {tpb, fpb, positives_boundary - tpb};
  return c;
}

FeatureTable FeatureTable::without_boundary_hits(const ClassThresholds& b) const {
  FeatureTable out;
  for (std::size_t i = 0; i < size(); ++i) {
    if (length[i] >= b.min_length && boundary_proj[i] >= b.min_projection &&
        boundary_angle[i] <= b.max_angle_deg)
      continue;
    out.length.push_back(length[i]);
    out.boundary_proj.push_back(boundary_proj[i]);
    out.boundary_angle.push_back(boundary_angle[i]);
    for (int k = 0; k < 2; ++k) {
      out.marking_proj[k].push_back(marking_proj[k][i]);
      out.marking_angle[k].push_back(marking_angle[k][i]);
    }
    out.truth.push_back(truth[i]);
    out.is_marking.push_back(is_marking[i]);
    out.is_boundary.push_back(is_boundary[i]);
  }
  out.positives_marking = positives_marking;
  out.positives_boundary = positives_boundary;
  return out;
}

}  // namespace fieldlines
