#pragma once
// A user's path as a CSV file (`sphere_sim terrain --path-file`, scripts/publish_path.py reads the
// same): rows `t,x,y` (a timed path: t [s] strictly increasing, relative to the first row) or
// `x,y` (an untimed one, followed at a speed), x and y [m] in the stack's fixed frame. A header
// row naming the columns is optional; empty lines and lines starting with '#' are skipped.

#include <optional>
#include <string>

#include "spherical_robots/terrain/sampled_path.hpp"

namespace spherical_robots::sphere_sim {

/// The path of the file at `file`; `speed` [m/s] times an x,y file and must be absent for a t,x,y
/// file. @throw UsageError for an x,y file without speed or a t,x,y file with one; InvalidInput
/// naming the file and the line for an unreadable file, a bad header, a row of the wrong length,
/// a cell that is not a number, a time or coordinate that is not finite, a time not after the
/// row before, or fewer than 2 points.
terrain::SampledPath readPathFile(const std::string& file, std::optional<double> speed);

}  // namespace spherical_robots::sphere_sim
