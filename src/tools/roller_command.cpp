#include "roller_command.hpp"

#include <cmath>
#include <ostream>
#include <vector>

#include "spherical_robots/roller/friction_drive.hpp"

namespace spherical_robots::sphere_sim {
namespace {

constexpr double kRadiansPerDegree = M_PI / 180.0;

enum class Mode { Inverse, Forward };

/// The command line, parsed and checked for syntax, before the core judges the values: a
/// malformed option is a usage error (exit 2) whatever the other values are.
struct RollerInputs {
  Mode mode = Mode::Inverse;
  double radius = 0.0;           // [m]
  std::vector<double> contacts;  // AZ1, EL1, AZ2, EL2 [deg]
  std::vector<double> alpha;     // α1, α2 [deg]
  double speed = 0.0;            // inverse: ‖V‖ [m/s]
  double direction = 0.0;        // inverse: φ [deg]
  roller::RollerSpeeds speeds;   // forward: v1, v2 [m/s]
};

/// Exactly one of the two modes, decided from which options are present.
Mode modeOf(const ParsedOptions& options) {
  const bool speed = options.given("speed");
  const bool direction = options.given("direction-deg");
  const bool forward = options.given("roller-speeds");
  if ((speed || direction) && forward) {
    throw UsageError(
        "give either --speed and --direction-deg (inverse) or --roller-speeds (forward), not both");
  }
  if (!speed && !direction && !forward) {
    throw UsageError(
        "no mode: give --speed and --direction-deg (inverse) or --roller-speeds (forward)");
  }
  if (speed != direction) {
    throw UsageError(speed ? "--speed needs --direction-deg" : "--direction-deg needs --speed");
  }
  return forward ? Mode::Forward : Mode::Inverse;
}

RollerInputs inputsFrom(const ParsedOptions& options) {
  RollerInputs inputs;
  inputs.mode = modeOf(options);
  inputs.radius = options.number("r");
  inputs.contacts = options.numberList("contacts", 4);
  inputs.alpha = options.numberList("alpha-deg", 2);
  if (inputs.mode == Mode::Inverse) {
    inputs.speed = options.number("speed");
    inputs.direction = options.number("direction-deg");
  } else {
    const std::vector<double> speeds = options.numberList("roller-speeds", 2);
    inputs.speeds = {speeds[0], speeds[1]};
  }
  return inputs;
}

roller::FrictionDrive driveFrom(const RollerInputs& inputs) {
  const std::vector<double>& c = inputs.contacts;
  return roller::FrictionDrive(roller::RollerGeometry(
      inputs.radius, {c[0] * kRadiansPerDegree, c[1] * kRadiansPerDegree},
      {c[2] * kRadiansPerDegree, c[3] * kRadiansPerDegree}, inputs.alpha[0] * kRadiansPerDegree,
      inputs.alpha[1] * kRadiansPerDegree));
}

double degrees(double radians) { return radians / kRadiansPerDegree; }

void writeJson(const RollerInputs& inputs, const roller::FrictionDrive& drive,
               const roller::DriveState& state, std::ostream& out) {
  JsonWriter json(out);
  json.text("mode", inputs.mode == Mode::Inverse ? "inverse" : "forward")
      .number("r", inputs.radius)
      .numbers("contacts_deg", inputs.contacts)
      .numbers("alpha_deg", inputs.alpha)
      .numbers("omega", {state.omega.x(), state.omega.y(), state.omega.z()})
      .number("speed", state.motion.speed)
      // Converting can round 359.99999999999997 up to 360: wrap again in degrees.
      .number("direction_deg", roller::wrapToPeriod(degrees(state.motion.direction), 360.0))
      .number("rho_deg", degrees(state.motion.rho))
      .number("v1", state.speeds.v1)
      .number("v2", state.speeds.v2)
      .number("S1", state.slip[0])
      .number("S2", state.slip[1])
      .number("constraint_line_gap", drive.constraintLineGap(state.speeds))
      .finish();
}

int runRollerCommand(const ParsedOptions& options, std::ostream& out) {
  const RollerInputs inputs = inputsFrom(options);
  const roller::FrictionDrive drive = driveFrom(inputs);
  const roller::DriveState state =
      inputs.mode == Mode::Inverse
          ? drive.inverse(inputs.speed, inputs.direction * kRadiansPerDegree)
          : drive.forward(inputs.speeds);
  OutputFile file(options.text("out"));
  writeJson(inputs, drive, state, file.stream());
  file.commit();
  out << "roller " << (inputs.mode == Mode::Inverse ? "inverse" : "forward") << ": |V| "
      << state.motion.speed << " m/s towards " << degrees(state.motion.direction) << " deg, rho "
      << degrees(state.motion.rho) << " deg; v1 " << state.speeds.v1 << " m/s, v2 "
      << state.speeds.v2 << " m/s; slip S1 " << state.slip[0] << " m/s, S2 " << state.slip[1]
      << " m/s\n";
  return kSuccess;
}

const char* const kDescription =
    R"(Two constraint rollers touch a sphere of radius r (centre O, frame x, y, z with z up) at
P1 and P2, P_i = r (cos AZ cos EL, sin AZ cos EL, sin EL) (eq 12). e = P1 x P2 / |P1 x P2| is
the normal of the plane through O, P1 and P2 (P1 to P2 counter-clockwise about e), and
X_i = e x P_i / r. Roller i turns about eta_i = X_i cos(alpha_i) + e sin(alpha_i) (eq 5); its
surface at P_i moves at v_i along e_i = P_i x eta_i / r (eq 2). The paper's section 3 drive is
--r 1 --contacts 215,60,325,60 --alpha-deg A,-A (A = 0, 10, 20, 30).

Inverse mode (--speed, --direction-deg): the sphere, rolling without slip on a floor below O,
is to move at V = speed (cos PHI, sin PHI, 0). omega is the angular velocity in the plane the
rollers can reach (eqs 17-19), and v1, v2 the roller speeds that drive it (eq 22).
Forward mode (--roller-speeds): omega from the roller speeds (eq 11); speed, direction and rho
from omega (eq 14). The rollers' constraint lines meet only if v1 sin(alpha1) =
v2 sin(alpha2); otherwise omega is the angular velocity with the least total squared slip
|zeta1|^2 + |zeta2|^2 (the midpoint of the lines' common perpendicular).

JSON members (numbers with 17 significant digits; SI units, angles in degrees):
  mode                 "inverse" or "forward"
  r, contacts_deg, alpha_deg   the inputs
  omega                [x, y, z] angular velocity of the sphere [rad/s]
  speed                |V| [m/s]; V = r (omega_y, -omega_x, 0)
  direction_deg        PHI of V [deg], in [0, 360), counter-clockwise from x
  rho_deg              elevation of omega above the xy plane [deg], in (-90, 90)
  v1, v2               roller peripheral speeds [m/s], signed as in eq 22
  S1, S2               slip velocities [m/s], signed: zeta_i = omega x P_i - v_i e_i = S_i X_i
                       (eq 28); S1 = -S2 = (v1 sin(alpha1) - v2 sin(alpha2)) / 2
  constraint_line_gap  distance between the constraint lines [rad/s], 0 when they meet
stdout: one line with the same figures rounded.

Exit status: 0 success; 2 usage error (unknown or repeated option, malformed number, wrong
list length, both modes or neither, --speed without --direction-deg or the reverse); 4 invalid
or degenerate input: one-line error on stderr and no output file (non-finite number, r <= 0,
speed < 0, P1 and P2 parallel or antipodal, cos(alpha_i) = 0, a vertical plane of reachable
omega where eq 18 divides by zero (inverse), an omega with no horizontal part, e.g. roller
speeds 0,0 (forward)). Near-zero tests use a threshold of 1e-9 on the dimensionless quantity.
)";

}  // namespace

Subcommand rollerCommand() {
  Subcommand command;
  command.name = "roller";
  command.summary =
      "Friction drive of two constraint rollers on a sphere, with slip (Kimura et al. 2019).";
  command.description = kDescription;
  command.options = {
      requiredOption("r", "R", "Sphere radius r [m], > 0."),
      requiredOption(
          "contacts", "AZ1,EL1,AZ2,EL2",
          "Azimuth and elevation of the contact points P1 and P2 [deg] (eq 12): azimuth from x\n"
          "towards y, elevation from the xy plane towards z. P1 and P2 must not be "
          "(anti)parallel."),
      requiredOption(
          "alpha-deg", "A1,A2",
          "Roller arrangement angles alpha1, alpha2 [deg] (eq 5): "
          "tilt of each roller's axis out of\n"
          "the plane through O, P1, P2, positive towards e. cos(alpha_i) must not be 0."),
      optionalOption("speed", "V",
                     "Inverse mode: desired speed |V| of the sphere's centre [m/s], >= 0. Needs\n"
                     "--direction-deg."),
      optionalOption(
          "direction-deg", "PHI",
          "Inverse mode: direction of V [deg], counter-clockwise from x (any value; output in\n"
          "[0, 360)). Needs --speed."),
      optionalOption(
          "roller-speeds", "V1,V2",
          "Forward mode: roller peripheral speeds v1, v2 [m/s], signed as in eq 22 (roller i's\n"
          "surface moves at v_i e_i). Not with --speed/--direction-deg."),
      outOption("JSON file to write (members below)."),
  };
  command.run = runRollerCommand;
  return command;
}

}  // namespace spherical_robots::sphere_sim
