#include "elsed.hpp"

namespace fieldlines {

void ElsedEngine::run(const cv::Mat&, const DetectorParams&, std::vector<Segment>&) {}

}  // namespace fieldlines
