#pragma once
// A terrain's heights sampled on a regular grid (a height map), before it is interpolated.

#include <Eigen/Core>
#include <string>

namespace spherical_robots::terrain {

/// Heights on a square grid: heights(i, j) = f(x0 + i h, y0 + j h), (x0, y0) = first_sample.
struct HeightGrid {
  Eigen::MatrixXd heights;                                 ///< [m]; rows along x, columns along y
  double spacing = 0.0;                                    ///< h [m] between neighbouring samples
  Eigen::Vector2d first_sample = Eigen::Vector2d::Zero();  ///< (x0, y0) [m] of heights(0, 0)
  std::string source;                                      ///< where it came from, for messages
};

/// The grid convolved with a Gaussian of standard deviation sigma [samples], separably along x
/// and then y, truncated at 4 sigma and normalised. Beyond an edge the samples are continued point-
/// symmetrically about the edge sample (z_-k = 2 z_0 - z_k), so a plane is left unchanged, slope
/// included. sigma = 0 returns the grid as it is.
/// @throw std::invalid_argument if sigma is negative or not finite, or if 4 sigma is not less
/// than either side's number of samples.
HeightGrid gaussianSmoothed(const HeightGrid& grid, double sigma);

}  // namespace spherical_robots::terrain
