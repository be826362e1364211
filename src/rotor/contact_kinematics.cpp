#include "spherical_robots/rotor/contact_kinematics.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

void requireFiniteCoordinates(const ContactCoordinates& c) {
  requireFinite(c.u_a, "u_a [R]");
  requireFinite(c.v_a, "v_a [R]");
  requireFinite(c.u_o, "u_o [rad]");
  requireFinite(c.v_o, "v_o [rad]");
  requireFinite(c.psi, "psi [rad]");
  if (std::cos(c.v_o) <= 0.0) {
    std::ostringstream message;
    message << "v_o [rad] must satisfy |v_o| < pi/2 (eqs 8, 10 divide by cos v_o), got " << c.v_o;
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

Eigen::Vector3d contactPoint(double u_o, double v_o) {
  requireFinite(u_o, "u_o [rad]");
  requireFinite(v_o, "v_o [rad]");
  return {-std::sin(u_o) * std::cos(v_o), std::sin(v_o), -std::cos(u_o) * std::cos(v_o)};  // eq 1
}

Eigen::Matrix3d orientation(double u_o, double v_o, double psi) {
  requireFinite(u_o, "u_o [rad]");
  requireFinite(v_o, "v_o [rad]");
  requireFinite(psi, "psi [rad]");
  const double cu = std::cos(u_o), su = std::sin(u_o);
  const double cv = std::cos(v_o), sv = std::sin(v_o);
  const double cp = std::cos(psi), sp = std::sin(psi);
  Eigen::Matrix3d r;
  // Columns n1, n2, n3 (eqs 3-5); n1_z is sin u_o cos v_o, not the printed cos u_o cos v_o (S1).
  r << cu * cp + su * sv * sp, cv * sp, -su * cp + cu * sv * sp,  //
      -cu * sp + su * sv * cp, cv * cp, su * sp + cu * sv * cp,    //
      su * cv, -sv, cu * cv;
  return r;
}

Eigen::Vector3d angularVelocity(const ContactCoordinates& coordinates, double u_o_rate,
                                double v_o_rate, double psi_rate) {
  requireFiniteCoordinates(coordinates);
  requireFinite(u_o_rate, "u_o rate [rad/s]");
  requireFinite(v_o_rate, "v_o rate [rad/s]");
  requireFinite(psi_rate, "psi rate [rad/s]");
  const double cv = std::cos(coordinates.v_o), sv = std::sin(coordinates.v_o);
  const double cp = std::cos(coordinates.psi), sp = std::sin(coordinates.psi);
  return {-u_o_rate * cv * sp - v_o_rate * cp,  // eq 18
          -u_o_rate * cv * cp + v_o_rate * sp,  // eq 19
          sv * u_o_rate - psi_rate};            // eq 17
}

ContactRates contactRates(const ContactCoordinates& coordinates, const Eigen::Vector3d& omega) {
  requireFiniteCoordinates(coordinates);
  requireFinite(omega.x(), "omega_x [rad/s]");
  requireFinite(omega.y(), "omega_y [rad/s]");
  requireFinite(omega.z(), "omega_z [rad/s]");
  const double cp = std::cos(coordinates.psi), sp = std::sin(coordinates.psi);
  const double across = omega.x() * sp + omega.y() * cp;
  ContactRates rates;
  rates.u_a = omega.y();                                          // eq 6
  rates.v_a = -omega.x();                                         // eq 7
  rates.u_o = -across / std::cos(coordinates.v_o);                // eq 8
  rates.v_o = -omega.x() * cp + omega.y() * sp;                   // eq 9
  rates.psi = -omega.z() - across * std::tan(coordinates.v_o);    // eq 10
  return rates;
}

}  // namespace spherical_robots::rotor
