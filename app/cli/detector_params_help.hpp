#pragma once
// The detector parameters a thresholds file sets, as a help section: one line per entry of
// kDetectorParamSpecs that files hold, with its default, valid range, unit and meaning.
#include <string>

namespace fieldlines::cli {

std::string detector_params_help();

}  // namespace fieldlines::cli
