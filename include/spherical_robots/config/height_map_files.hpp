#pragma once
// The raster files a height map comes in: single-channel PNG (libpng), binary PGM, CSV grid.

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace spherical_robots::config {

/// A single-channel image's grey levels as stored, no gamma applied: levels(r, c) is the pixel
/// in row r from the top, column c from the left.
struct GreyImage {
  Eigen::Matrix<std::uint16_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> levels;
  unsigned max_level = 0;  ///< the level of white: 255 (8-bit), 65535 (16-bit), a PGM's maxval
};

/// An 8- or 16-bit greyscale PNG (colour type grey, no alpha; interlaced or not).
/// @throw std::invalid_argument naming the file: unreadable, not a PNG, corrupt, or not 8- or
/// 16-bit grey (the message says what it is).
GreyImage readPng(const std::string& path);

/// A binary (P5) PGM, maxval 1 .. 65535 (two bytes a sample, most significant first, above 255).
/// @throw std::invalid_argument naming the file and, for a bad sample, the pixel (row, column)
/// and maxval: unreadable, not P5, a bad header, a sample above maxval, fewer samples than the
/// header promises.
GreyImage readPgm(const std::string& path);

/// A grid of heights [m], one line of comma-separated numbers per row: result(r, c) is line
/// r + 1's c-th number. Blank lines and lines starting with '#' are skipped.
/// @throw std::invalid_argument naming the file, the line and the column: a cell that is not a
/// finite number, a line with another number of cells than the first, no rows.
Eigen::MatrixXd readCsvGrid(const std::string& path);

}  // namespace spherical_robots::config
