#pragma once
// A height map's YAML description (map_server- and Gazebo-like) into the grid of heights a
// terrain::HeightMapSurface interpolates (docs/conventions.md, "Height maps").

#include <string>
#include <vector>

#include "spherical_robots/terrain/height_grid.hpp"

namespace spherical_robots::config {

/// The smoothing [pixels, the Gaussian's sigma] an 8-bit image gets unless its YAML says
/// otherwise: on eq 59 (0.8 m range, one grey level 3 mm) at 0.05 m a pixel it cuts the Hessian's
/// error from 6.9 to 0.044 1/m (docs/conventions.md, "Height maps", "8-bit images").
constexpr double kEightBitSmoothing = 2.0;

struct LoadedHeightMap {
  terrain::HeightGrid grid;           ///< smoothed if the description (or an 8-bit image) asks
  double smoothing = 0.0;             ///< the sigma applied [pixels]
  std::vector<std::string> warnings;  ///< one line each, for the log (an 8-bit image)
};

/// Reads a height map's YAML description and the image or CSV grid it names (a relative path is
/// relative to the YAML's directory):
///   image: FILE.png | FILE.pgm   (8- or 16-bit grey; or csv: FILE.csv, heights in metres)
///   resolution: 0.05             [m/pixel]
///   origin: [x, y] or [x, y, 0]  [m], the outer corner of the bottom-left pixel (map_server)
///   min_height: -0.4             [m], grey level 0 (images only)
///   max_height: 0.4              [m], white (images only)
///   smoothing: 0                 [pixels] optional Gaussian sigma; default 0, for 8-bit 2
/// The image's top row is the map's +y edge and its left column the -x edge; a CSV grid is laid
/// out as the image would be. Each pixel is a sample at its centre.
/// @throw std::invalid_argument naming the file, the key or the line/pixel, and the limit.
LoadedHeightMap loadHeightMap(const std::string& yaml_path);

}  // namespace spherical_robots::config
