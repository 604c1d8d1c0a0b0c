#pragma once
// What every subcommand does alike: answer -h/--help on stdout, and take its output files and
// check them before any long work (so a bad path fails in a second, not after the batch).
//
//   const auto a = parse_or_print_help(args, {"-o", "--output", "--json"}, {"--quiet"}, kHelp);
//   if (!a) return 0;
//   const fs::path out = required_output_path(*a, "-o", "FILE", a->positionals());
//   const auto report = output_path(*a, "--json", a->positionals());
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/args.hpp"
#include "app/cli/commands.hpp"

namespace fieldlines::cli {

// True when -h or --help is one of `args` (before a "--"), wherever it stands: in
// `eval --gt --help` the parser alone would take --help as --gt's value.
bool help_requested(const Args& args);

// Parses `args` as ParsedArgs does, with -h and --help accepted besides `flag_options`. When
// help is asked for, prints `help` on stdout and returns nothing: the command then exits 0.
std::optional<ParsedArgs> parse_or_print_help(const Args& args, std::set<std::string> value_options,
                                              std::set<std::string> flag_options, std::string_view help);

// The file `option` names ("-o" also reads "--output"), checked now: its folder exists, it is
// not a folder, and it is none of `inputs`. Nothing when the option is not given. Throws
// fieldlines::Error naming the option and the path.
std::optional<std::filesystem::path> output_path(const ParsedArgs& a, std::string_view option,
                                                 const std::vector<std::string>& inputs = {});

// The same for a required option: throws "missing -o FILE (see --help)" (`placeholder` = FILE)
// when it is not given.
std::filesystem::path required_output_path(const ParsedArgs& a, std::string_view option, std::string_view placeholder,
                                           const std::vector<std::string>& inputs = {});

}  // namespace fieldlines::cli
