#pragma once
// The `fieldlines` subcommands. Each lives in its own cmd_<name>.cpp and returns the exit code:
// 0 success, 1 some inputs failed (batch went on), 2 usage or fatal error.
#include <string>
#include <vector>

namespace fieldlines::cli {

using Args = std::vector<std::string>;  // the arguments after the subcommand name

int run(int argc, char** argv);  // dispatch, --help, --version

int cmd_detect(const Args& args);
int cmd_bench(const Args& args);
int cmd_train(const Args& args);
int cmd_eval(const Args& args);
int cmd_sweep(const Args& args);
int cmd_synth(const Args& args);
int cmd_autolabel(const Args& args);
int cmd_convert(const Args& args);
int cmd_calibrate(const Args& args);
int cmd_calibrate_camera(const Args& args);
int cmd_eval_gt(const Args& args);  // `eval --gt` (cmd_eval_gt.cpp)

}  // namespace fieldlines::cli
