#include "model/limits.hpp"

#include <cstdio>
#include <string>

namespace tendril {

void check_coordinates(const Vec3& x, const char* what) {
  if (x.cwiseAbs().maxCoeff() <= kMaxCoordinate) return;  // false for NaN too
  char buf[160];
  std::snprintf(buf, sizeof buf, ": position (%g, %g, %g) is beyond %g m from the origin", x.x(), x.y(), x.z(),
                kMaxCoordinate);
  throw ModelError(what + std::string(buf));
}

}  // namespace tendril
