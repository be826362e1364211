// A height map's YAML description (config::loadHeightMap), the grid it names, its smoothing,
// and the surface made of it (config::makeSurface, as the terrain plant does). The YAML is the
// input; beside it lie a small CSV grid (grid.csv) and binary PGM (grid.pgm) that it may name,
// written once. Errors name the YAML or the file it names.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "fuzz_input.hpp"
#include "spherical_robots/config/height_map_loader.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/terrain/height_map_surface.hpp"

namespace {

/// The scratch directory, with grid.csv and grid.pgm: 8 x 8 samples of a bump.
std::string mapDirectory() {
  const std::string& directory = spherical_robots::fuzz::scratchDirectory();
  std::ofstream csv(directory + "/grid.csv"), pgm(directory + "/grid.pgm", std::ios::binary);
  pgm << "P5\n8 8\n255\n";
  for (int r = 0; r < 8; ++r) {
    for (int c = 0; c < 8; ++c) {
      const int level = (r * c * 4) % 256;
      csv << (c ? "," : "") << level / 1000.0;
      pgm.put(static_cast<char>(level));
    }
    csv << '\n';
  }
  return directory;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  static const std::string directory = mapDirectory();
  const std::string path = fuzz::inputFile(data, size, "map.yaml");
  try {
    config::loadHeightMap(path);
    config::SurfaceSpec spec;
    spec.type = "height_map";
    spec.height_map = path;
    config::makeSurface(spec)->maxPrincipalCurvature();
  } catch (const std::invalid_argument& error) {
    fuzz::requireNamesFile(error, directory);
  }
  return 0;
}
