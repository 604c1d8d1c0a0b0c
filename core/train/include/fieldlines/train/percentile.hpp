#pragma once
// Order statistics, the one definition the calibration, the sweeps and the reports share.
#include <vector>

namespace fieldlines {

// Linear interpolation between order statistics (numpy's default); 0 for an empty set.
double percentile(std::vector<double> values, double p);
// percentile(values, 50).
double median(std::vector<double> values);

}  // namespace fieldlines
