#include "spherical_robots/core/angles.hpp"

#include <cmath>

namespace spherical_robots {

double wrapToPi(double angle) {
  const double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [−π, π]
  return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

}  // namespace spherical_robots
