// The roller stack's drive as config/roller.yaml and the URDF describe it: roller::RollerGeometry
// (sphere radius, contact directions, arrangement angles), the friction drive and the motors'
// actuation (roller radius), then both kinematics at a command. Input: sphere radius,
// azimuth1, elevation1, azimuth2, elevation2, alpha1, alpha2 [rad], roller radius, speed,
// direction, v1, v2, roll, lateral and turn rates.
#include <stdexcept>

#include "fuzz_input.hpp"
#include "spherical_robots/roller/friction_drive.hpp"
#include "spherical_robots/roller/roller_actuation.hpp"
#include "spherical_robots/roller/roller_geometry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  fuzz::FuzzNumbers in(data, size);
  const double radius = in.next();
  const roller::SphericalDirection contact1{in.next(), in.next()};
  const roller::SphericalDirection contact2{in.next(), in.next()};
  const double alpha1 = in.next(), alpha2 = in.next(), roller_radius = in.next();
  const double speed = in.next(), direction = in.next();
  const roller::RollerSpeeds speeds{in.next(), in.next()};
  const terrain::DriveRates rates{in.next(), in.next(), in.next()};
  try {
    const roller::FrictionDrive drive(
        roller::RollerGeometry(radius, contact1, contact2, alpha1, alpha2));
    const roller::RollerActuation actuation(drive, roller_radius);
    drive.inverse(speed, direction);
    drive.forward(speeds);
    actuation.driveRates(actuation.setpoints(rates));
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
