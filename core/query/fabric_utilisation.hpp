#pragma once
// The utilisation of a CST triangle of fabric (issue 14): its warp and weft
// tension over the fabric's strip-tensile strengths (tendril.fabric,
// model/materials.hpp), the larger of the two. Compression counts 0 (a
// membrane wrinkles, it does not fail), and shear is not checked (fabric
// makers give no shear strength).
#include <algorithm>

#include "query/element_results.hpp"

namespace tendril {

inline double fabric_utilisation(const TriangleResult& t, double strength_warp, double strength_weft) {
  return std::max(std::max(t.warp, 0.0) / strength_warp, std::max(t.weft, 0.0) / strength_weft);
}

}  // namespace tendril
