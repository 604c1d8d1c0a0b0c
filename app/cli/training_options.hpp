#pragma once
// Options shared by `train` and `sweep`: protocol, class, objective, PSO, bounds, gradient mode.
#include <set>
#include <string>

#include "app/cli/args.hpp"
#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/train/protocols.hpp"

namespace fieldlines::cli {

// The value options read by apply_training_options (add them to the parser).
const std::set<std::string>& training_value_options();
inline constexpr const char* kTrainingOptionsHelp =
    R"(  --protocol P         ours (default) or paper: sets all of the following, which then override
  --class C            marking (default), boundary or both
  --objective O        tp-fp:C = TP - C FP (ours tp-fp:1.5), tp-fp (the paper's), f1 or fbeta:B
  --particles N        PSO swarm size (100)
  --iterations N       PSO iterations (ours 100, paper 10)
  --inertia W          PSO inertia (ours 0.7, paper 0.1)
  --cognitive C        PSO pull to a particle's own best (ours 1.5, paper 0.5)
  --social C           PSO pull to the swarm's best (ours 1.5, paper 0.5)
  --polish on|off      exact breakpoint polish after PSO (ours on, paper off)
  --projection-range LO:HI   min projection search range (10:255)
  --angle-range LO:HI        max angle search range, degrees (20:70)
  --length-range LO:HI       min length search range (ours 0:300, paper 50:300)
  --gradient G         axes (default, the reference) or normal (orientation-invariant)
  --threads N          threads scoring the swarm (1)
)";

// Starts from protocol_spec(--protocol) and applies every option given; sets `start.mode`.
// Throws fieldlines::Error on malformed values.
ProtocolSpec apply_training_options(const ParsedArgs& a, Thresholds& start);

}  // namespace fieldlines::cli
