#include "commands.hpp"
#include "fieldlines/error.hpp"

namespace fieldlines::cli {

// Placeholder until this command is implemented; it fails loudly rather than pretend.
int cmd_train(const Args&) { throw Error("'train' is not implemented yet"); }

}  // namespace fieldlines::cli
