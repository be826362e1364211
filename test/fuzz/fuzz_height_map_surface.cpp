// A height map's grid as loadHeightMap hands it over: terrain::gaussianSmoothed, then the
// HeightMapSurface's spline and curvature bounds, then the surface at a point.
// Input: rows, columns (0 .. 12), spacing, x0, y0, sigma, x, y, then the heights row by row.
#include <stdexcept>

#include "fuzz_input.hpp"
#include "spherical_robots/terrain/height_grid.hpp"
#include "spherical_robots/terrain/height_map_surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  fuzz::FuzzNumbers in(data, size);
  terrain::HeightGrid grid;
  const int rows = in.nextCount(12), columns = in.nextCount(12);
  grid.spacing = in.next();
  grid.first_sample = {in.next(), in.next()};
  grid.source = "fuzz";
  const double sigma = in.next(), x = in.next(), y = in.next();
  grid.heights.resize(rows, columns);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) grid.heights(r, c) = in.next();
  }
  try {
    const terrain::HeightMapSurface surface(terrain::gaussianSmoothed(grid, sigma));
    surface.maxPrincipalCurvature();
    surface.maxCurvatureLocation();
    surface.describe();
    surface.evaluate(x, y);
  } catch (const std::invalid_argument&) {
  } catch (const terrain::OffMapError&) {
  }
  return 0;
}
