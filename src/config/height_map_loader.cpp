#include "spherical_robots/config/height_map_loader.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/config/height_map_files.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"

namespace spherical_robots::config {
namespace {

const std::vector<std::string> kKeys = {"image",      "csv",        "resolution", "origin",
                                        "min_height", "max_height", "smoothing"};

std::string joinedKeys() {
  std::string text;
  for (const std::string& key : kKeys) text += (text.empty() ? "" : ", ") + key;
  return text;
}

std::invalid_argument keyError(const ParameterSource& source, const std::string& key,
                               const std::string& what) {
  return std::invalid_argument(source.origin() + ": '" + key + "' " + what);
}

/// Heights(i, j) along (x, y) from rows top-down, columns left-right, as an image stores them.
Eigen::MatrixXd fromImageLayout(const Eigen::MatrixXd& rows_down) {
  return rows_down.colwise().reverse().transpose();
}

}  // namespace

LoadedHeightMap loadHeightMap(const std::string& yaml_path) {
  const YamlParameterSource source(yaml_path);
  for (const std::string& key : source.keys("").value_or(std::vector<std::string>{})) {
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
      throw keyError(source, key, "is not a height map key (" + joinedKeys() + ")");
  }
  const std::optional<std::string> image = source.text("image");
  const std::optional<std::string> csv = source.text("csv");
  if (image.has_value() == csv.has_value())
    throw std::invalid_argument(yaml_path + ": give exactly one of 'image' and 'csv'");
  const std::filesystem::path directory = std::filesystem::path(yaml_path).parent_path();
  const std::string data_path = (directory / (image ? *image : *csv)).string();

  LoadedHeightMap map;
  terrain::HeightGrid& grid = map.grid;
  grid.source = data_path;
  if (!source.number("resolution")) throw keyError(source, "resolution", "is missing [m/pixel]");
  grid.spacing = positiveNumber(source, "resolution", 0.0);
  const std::vector<double> origin = source.numbers("origin").value_or(std::vector<double>{});
  if (origin.size() < 2 || origin.size() > 3 || (origin.size() == 3 && origin[2] != 0.0)) {
    throw keyError(source, "origin",
                   "must be [x, y] or [x, y, 0] in metres (a rotated map is not supported)");
  }
  grid.first_sample = Eigen::Vector2d(origin[0], origin[1]) + Eigen::Vector2d::Constant(grid.spacing / 2.0);
  for (const char* key : {"min_height", "max_height"}) {
    if (csv && source.number(key))
      throw keyError(source, key, "applies to images only (a CSV grid holds heights in metres)");
  }

  double default_smoothing = 0.0;
  if (csv) {
    grid.heights = fromImageLayout(readCsvGrid(data_path));
  } else {
    const std::string extension = std::filesystem::path(*image).extension().string();
    GreyImage grey;
    if (extension == ".png" || extension == ".PNG") {
      grey = readPng(data_path);
    } else if (extension == ".pgm" || extension == ".PGM") {
      grey = readPgm(data_path);
    } else {
      throw keyError(source, "image", "'" + *image + "' must be a .png or .pgm file");
    }
    for (const char* key : {"min_height", "max_height"}) {
      if (!source.number(key)) throw keyError(source, key, "is missing [m] (the image's height range)");
    }
    const double low = finiteNumber(source, "min_height", 0.0);
    const double high = finiteNumber(source, "max_height", 0.0);
    if (!(high > low)) {
      std::ostringstream what;
      what << "= " << high << " m must be above min_height = " << low << " m";
      throw keyError(source, "max_height", what.str());
    }
    const double per_level = (high - low) / grey.max_level;
    // (high - low) * level / max_level: black and white land exactly on min and max_height.
    grid.heights = fromImageLayout(
        (low + (high - low) * grey.levels.cast<double>().array() / grey.max_level).matrix());
    if (grey.max_level <= 255) {
      default_smoothing = kEightBitSmoothing;
      std::ostringstream warning;
      warning << data_path << ": " << grey.max_level + 1 << " grey levels: one is " << per_level
              << " m, Hessian noise of order " << per_level / (grid.spacing * grid.spacing)
              << " 1/m at " << grid.spacing << " m/pixel";
      map.warnings.push_back(warning.str());
    }
  }
  map.smoothing = nonNegativeNumber(source, "smoothing", default_smoothing);
  if (!map.warnings.empty()) {
    std::ostringstream warning;
    warning << data_path << ": smoothed with a Gaussian of sigma " << map.smoothing
            << " pixels (docs/conventions.md, \"8-bit images\"); a 16-bit PNG or PGM, or a CSV "
               "grid, keeps the surveyed curvature";
    map.warnings.push_back(warning.str());
  }
  grid = terrain::gaussianSmoothed(grid, map.smoothing);
  return map;
}

}  // namespace spherical_robots::config
