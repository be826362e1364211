#include "spherical_robots/terrain/height_grid.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::terrain {
namespace {

constexpr double kTruncation = 4.0;  // [sigma]: the tail beyond holds 6e-5 of the weight

/// Each column of `samples` convolved with `kernel` (odd length, centred), the column continued
/// point-symmetrically beyond both ends.
Eigen::MatrixXd convolveColumns(const Eigen::MatrixXd& samples, const std::vector<double>& kernel) {
  const Eigen::Index n = samples.rows();
  const Eigen::Index radius = static_cast<Eigen::Index>(kernel.size() / 2);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(n, samples.cols());
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index k = -radius; k <= radius; ++k) {
      const Eigen::Index source = i + k;
      const double weight = kernel[static_cast<std::size_t>(k + radius)];
      if (source < 0) {
        result.row(i) += weight * (2.0 * samples.row(0) - samples.row(-source));
      } else if (source >= n) {
        result.row(i) += weight * (2.0 * samples.row(n - 1) - samples.row(2 * (n - 1) - source));
      } else {
        result.row(i) += weight * samples.row(source);
      }
    }
  }
  return result;
}

}  // namespace

HeightGrid gaussianSmoothed(const HeightGrid& grid, double sigma) {
  requireNonNegative(sigma, "height map smoothing sigma [samples]");
  if (sigma == 0.0) return grid;
  // Compared as a double: a huge sigma's reach does not fit an Eigen::Index.
  const double reach = std::ceil(kTruncation * sigma);
  if (reach >= static_cast<double>(grid.heights.rows()) ||
      reach >= static_cast<double>(grid.heights.cols())) {
    std::ostringstream message;
    message << grid.source << ": smoothing sigma " << sigma << " samples reaches " << reach
            << " samples, which must be less than the map's " << grid.heights.rows() << " x "
            << grid.heights.cols() << " samples";
    throw std::invalid_argument(message.str());
  }
  const auto radius = static_cast<Eigen::Index>(reach);
  std::vector<double> kernel(static_cast<std::size_t>(2 * radius + 1));
  double total = 0.0;
  for (Eigen::Index k = -radius; k <= radius; ++k) {
    const double weight = std::exp(-0.5 * static_cast<double>(k * k) / (sigma * sigma));
    kernel[static_cast<std::size_t>(k + radius)] = weight;
    total += weight;
  }
  for (double& weight : kernel) weight /= total;
  HeightGrid smoothed = grid;
  smoothed.heights = convolveColumns(convolveColumns(grid.heights, kernel).transpose(), kernel)
                         .transpose();
  return smoothed;
}

}  // namespace spherical_robots::terrain
