#include "app/cli/subcommand.hpp"

#include <cstdio>

#include "app/cli/output_file.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines::cli {

bool help_requested(const Args& args) {
  for (const std::string& arg : args) {
    if (arg == "--") return false;
    if (arg == "-h" || arg == "--help") return true;
  }
  return false;
}

std::optional<ParsedArgs> parse_or_print_help(const Args& args, std::set<std::string> value_options,
                                              std::set<std::string> flag_options, std::string_view help) {
  if (help_requested(args)) {
    std::fwrite(help.data(), 1, help.size(), stdout);
    return std::nullopt;
  }
  flag_options.insert({"-h", "--help"});
  return ParsedArgs(args, std::move(value_options), std::move(flag_options));
}

std::optional<std::filesystem::path> output_path(const ParsedArgs& a, std::string_view option,
                                                 const std::vector<std::string>& inputs) {
  const std::string name(option);
  std::optional<std::string> value = a.value(name);
  if (!value && name == "-o") value = a.value("--output");
  if (!value) return std::nullopt;
  const std::filesystem::path path = *value;
  check_output_path(option, path);
  check_not_an_input(option, path, inputs);
  return path;
}

std::filesystem::path required_output_path(const ParsedArgs& a, std::string_view option, std::string_view placeholder,
                                           const std::vector<std::string>& inputs) {
  std::optional<std::filesystem::path> path = output_path(a, option, inputs);
  if (!path) throw Error("missing " + std::string(option) + " " + std::string(placeholder) + " (see --help)");
  return *path;
}

}  // namespace fieldlines::cli
