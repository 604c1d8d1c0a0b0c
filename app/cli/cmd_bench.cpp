#include "commands.hpp"
#include "fieldlines/error.hpp"

namespace fieldlines::cli {

// Placeholder until this command is implemented; it fails loudly rather than pretend.
int cmd_bench(const Args&) { throw Error("'bench' is not implemented yet"); }

}  // namespace fieldlines::cli
