#include "spherical_robots/terrain/pursuit_law.hpp"

#include <stdexcept>

namespace spherical_robots::terrain::pursuit_law_detail {

void rejectDesiredPoint() {
  throw std::invalid_argument("tracking error: desired point not finite");
}

}  // namespace spherical_robots::terrain::pursuit_law_detail
