// config::makeSurface over the surface parameters of config/terrain.yaml (terrain/surface/...),
// then the surface at a point and the single-point contact check for a sphere's radius.
// Input: type (0 cosine, 1 plane, 2 tilted_plane), amplitude, frequency, slope_x, slope_y,
// offset, x, y, radius.
#include <array>
#include <stdexcept>

#include "fuzz_input.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/terrain/surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  static const std::array<const char*, 3> kTypes = {"cosine", "plane", "tilted_plane"};
  fuzz::FuzzNumbers in(data, size);
  config::SurfaceSpec spec;
  spec.type = kTypes[static_cast<std::size_t>(in.nextCount(2))];
  spec.amplitude = in.next();
  spec.frequency = in.next();
  spec.slope_x = in.next();
  spec.slope_y = in.next();
  spec.offset = in.next();
  const double x = in.next(), y = in.next(), radius = in.next();
  try {
    const auto surface = config::makeSurface(spec);
    surface->evaluate(x, y);
    terrain::principalCurvatures(*surface, x, y);
    surface->describe();
    terrain::requireSinglePointContact(*surface, radius);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
