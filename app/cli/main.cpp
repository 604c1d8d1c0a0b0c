#include "app/cli/commands.hpp"

int main(int argc, char** argv) { return fieldlines::cli::run(argc, argv); }
