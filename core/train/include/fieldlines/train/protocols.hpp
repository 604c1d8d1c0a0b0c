#pragma once
// Named training protocols: the paper's (to reproduce its Table 3) and ours (the default).
#include <string_view>

#include "fieldlines/train/splits.hpp"
#include "fieldlines/train/training.hpp"

namespace fieldlines {

enum class Protocol { Paper, Ours };
std::string_view to_string(Protocol p);
bool parse_protocol(std::string_view text, Protocol& out);  // "paper" or "ours"

struct ProtocolSpec {
  TrainParams train;
  SplitMode split = SplitMode::ByImage;
};

// Paper: row split; PSO 100 particles x 10 iterations, inertia 0.1, c1 = c2 = 0.5; reference
// bounds; TP - FP on the marking class; no polish.
// Ours: image split; PSO 100 x 100, inertia 0.7, c1 = c2 = 1.5; exact polish; TP - 1.5 FP on
// the marking class; reference bounds except min length 0-300 (see docs/training.md for why).
ProtocolSpec protocol_spec(Protocol p);

}  // namespace fieldlines
