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
// The help lines of those options, each protocol's value read from protocol_spec().
std::string training_options_help();

// Starts from protocol_spec(--protocol) and applies every option given; sets `start.mode`.
// Throws fieldlines::Error on malformed values.
ProtocolSpec apply_training_options(const ParsedArgs& a, Thresholds& start);

}  // namespace fieldlines::cli
