#pragma once
// Named training protocols: the paper's (to reproduce its Table 3) and ours (the default).
#include <string>
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

// What each protocol sets is defined once, in protocol_spec() (protocols.cpp says why);
// protocol_summary() states it for help texts and panels. Paper: the paper's settings, to
// reproduce its Table 3. Ours: a swarm that converges, the exact polish, an image split and a
// costlier false positive (see docs/training.md).
ProtocolSpec protocol_spec(Protocol p);

// One line from protocol_spec(p): "<split> split; PSO <n> particles x <k> iterations, inertia
// <w>, c1 <c1>, c2 <c2>; exact polish|no polish; objective <name> on <class>; search box
// projection <lo>:<hi>, angle <lo>:<hi> deg, length <lo>:<hi>".
std::string protocol_summary(Protocol p);

}  // namespace fieldlines
