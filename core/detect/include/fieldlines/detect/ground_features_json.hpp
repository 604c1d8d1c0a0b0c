#pragma once
// The field features on the ground (ground_features.hpp) as JSON, in soccer_vision_3d_msgs'
// names: geometry_msgs points {x, y, z} in metres (z = 0 on the turf), each point's covariance
// beside it as [xx, xy, yy] (m^2). `fieldlines detect --json` writes it as an image's "ground",
// the Python module's Detector.ground_features() returns it.
//
// {"segments":[{"start","end","width","start_covariance","end_covariance"}],
//  "intersections":[{"center","center_covariance","type","num_rays","rays":[{x,y,z}],"confidence"}],
//  "ellipses":[{"center":{"position","orientation"},"diameter","center_covariance","confidence"}],
//  "field_boundary":{"points":[{x,y,z}],"covariances":[[xx,xy,yy]]}}
#include <nlohmann/json.hpp>

#include "fieldlines/detect/ground_features.hpp"

namespace fieldlines {

// Lengths at a micrometre, confidences likewise rounded; a value that is not finite (none
// should be) as 0.
nlohmann::ordered_json to_json(const GroundFeatures& ground);

}  // namespace fieldlines
