#pragma once
// The pursuit controller's tracking step with time as a number (no ROS): the path's clock starts
// at the first command (or, for a path received later, as follow() decides), the desired point is
// lifted onto the surface, and the law's command is checked before it leaves. The controller node and the batch run that replays the stack
// (SampledTerrainLoop) both call this, so that they compute the same command from the same input.

#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::terrain {

/// One tracking step's figures: the desired point, the error to it and the drive-rate set-points.
struct TrackingCommand {
  DesiredPoint desired;
  TrackingError error;
  DriveRates rates;  ///< set-points [rad/s], as the law gives them (not yet realised)
};

class PathTracker {
 public:
  /// The law, path and surface must outlive the tracker (the path until another replaces it).
  PathTracker(const PursuitController& law, const ReferencePath& path, const Surface& surface);

  /// Commands with `law` from the next command on (new gains, or the other law), the path and its
  /// clock unchanged. `law` must outlive the tracker or the next setLaw().
  void setLaw(const PursuitController& law);

  /// Follows `path` from now on, a path received at `received` [ns] whose first point is stamped
  /// `first_stamp` [ns]: its clock starts at first_stamp if that is after `received` (until then
  /// the desired point holds the path's start, at rest); otherwise at the next command, as the
  /// built-in paths start at the first. `path` must outlive the tracker or the next follow().
  void follow(const ReferencePath& path, Nanoseconds first_stamp, Nanoseconds received);

  /// The command at `now` [ns] for the robot at `geometry` with RS tilt `tilt` [rad]. Unless
  /// follow() set it, the path's clock starts at the first call: p_d is taken at now - that time,
  /// in seconds as ROS gives them (stampSeconds). @throw std::invalid_argument if the law's input or output is not
  /// finite; nothing changes then except the path's start.
  TrackingCommand command(Nanoseconds now, const ContactGeometry& geometry, double tilt);

  /// The clock jumped by `jump` [s]: the path's clock moves with it, so the reference continues
  /// from where it was (its start is never before time 0).
  void shiftStart(double jump);

  bool started() const { return started_; }
  const PursuitController& law() const { return *law_; }
  const ReferencePath& path() const { return *path_; }

 private:
  const PursuitController* law_;
  const ReferencePath* path_;
  const Surface& surface_;
  bool started_ = false;
  Nanoseconds start_ = 0;
};

}  // namespace spherical_robots::terrain
