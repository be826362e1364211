#include "spherical_robots/terrain/path_tracker.hpp"

#include <algorithm>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::terrain {

PathTracker::PathTracker(const PursuitController& law, const ReferencePath& path,
                         const Surface& surface)
    : law_(&law), path_(&path), surface_(surface) {}

void PathTracker::setLaw(const PursuitController& law) { law_ = &law; }

void PathTracker::follow(const ReferencePath& path, Nanoseconds first_stamp, Nanoseconds received) {
  path_ = &path;
  started_ = first_stamp > received;
  start_ = started_ ? first_stamp : 0;
}

TrackingCommand PathTracker::command(Nanoseconds now, const ContactGeometry& geometry,
                                     double tilt) {
  if (!started_) {
    started_ = true;
    start_ = now;
  }
  TrackingCommand result;
  if (now < start_) {  // a path whose first stamp is still ahead: wait at its start
    result.desired = liftOntoSurface(*path_, surface_, 0.0);
    result.desired.velocity.setZero();
  } else {
    result.desired =
        liftOntoSurface(*path_, surface_, stampSeconds(now - start_), law_->velocityWindow());
  }
  result.error = trackingError(geometry, result.desired.position);
  result.rates = law_->command(geometry, tilt, result.error, result.desired.velocity);
  // Nothing non-finite leaves the controller.
  requireFinite(result.error.norm, "|e_t|");
  requireFinite(result.error.zeta, "zeta");
  requireFinite(result.rates.roll_rate, "roll rate set-point");
  requireFinite(result.rates.lateral_rate, "lateral rate set-point");
  requireFinite(result.rates.turn_rate, "turn rate set-point");
  return result;
}

void PathTracker::shiftStart(double jump) {
  if (started_) start_ = std::max<Nanoseconds>(0, start_ + durationNanoseconds(jump));
}

}  // namespace spherical_robots::terrain
