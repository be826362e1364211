// The URDF readers (urdfdom under them): config::sphereRadiusFromUrdf of the links the stacks
// read, and config::normaParametersFromUrdf. Input: the XML text.
#include <stdexcept>
#include <string>

#include "fuzz_input.hpp"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/config/robot_description.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    config::sphereRadiusFromUrdf(xml, "base_link");
  } catch (const std::invalid_argument&) {
  }
  try {
    config::normaParametersFromUrdf(xml);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
