#include "freebot_command.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/freebot/src_inverse_kinematics.hpp"
#include "spherical_robots/freebot/src_manipulator.hpp"
#include "spherical_robots/freebot/trolley_drive.hpp"

namespace spherical_robots::sphere_sim {
namespace {

using freebot::IkMode;
using freebot::IkOptions;
using freebot::IkResult;
using freebot::LinkPose;
using freebot::SrcJoint;
using freebot::SrcJointState;
using freebot::SrcManipulator;

constexpr double kDegreesPerRadian = 180.0 / M_PI;

std::vector<double> wxyz(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }
std::vector<double> xyz(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// FreeBOT's parameters as the stack's nodes read them: DIR/config/freebot.yaml.
config::YamlParameterSource freebotConfig(const ParsedOptions& options) {
  return config::YamlParameterSource(configDirectory(options) + "/config/freebot.yaml");
}

/// --radii checked for syntax, or the configuration's chain; the core judges the values (a radius
/// <= 0 is exit 4).
std::vector<double> radiiFrom(const ParsedOptions& options) {
  if (!options.given("radii"))
    return config::freebotChain(freebotConfig(options)).manipulator().radii();
  const std::vector<double> radii = options.numberList("radii");
  if (radii.size() < 2) {
    throw UsageError("--radii: give L0,L1,...,Ln with n >= 1 (the base's radius and one per link)");
  }
  return radii;
}

/// A ';'-separated joint list must have one group per joint: a count mismatch is a usage error.
std::vector<std::vector<double>> jointGroups(const ParsedOptions& options, const std::string& name,
                                             std::size_t per_joint, std::size_t joints) {
  std::vector<std::vector<double>> groups = options.numberGroups(name, per_joint);
  if (groups.size() != joints) {
    throw UsageError("--" + name + ": " + std::to_string(groups.size()) +
                     " joints given, but --radii has " + std::to_string(joints + 1) +
                     " radii, i.e. " + std::to_string(joints) + " joints");
  }
  return groups;
}

std::vector<SrcJointState> rotationVectorJoints(const SrcManipulator& chain,
                                                const std::vector<std::vector<double>>& groups) {
  std::vector<Eigen::Vector2d> vectors;
  for (const std::vector<double>& g : groups) {
    vectors.emplace_back(g[0], g[1]);
  }
  return chain.straightRolls(vectors);
}

std::vector<SrcJointState> quaternionJoints(const SrcManipulator& chain,
                                            const std::vector<std::vector<double>>& groups) {
  std::vector<SrcJointState> joints;
  for (const std::vector<double>& g : groups) {
    joints.push_back(
        {Eigen::Quaterniond(g[0], g[1], g[2], g[3]), Eigen::Quaterniond(g[4], g[5], g[6], g[7])});
  }
  chain.requireValid(joints);
  return joints;
}

/// The rows of J_{B_n}, each an array.
void writeMatrix(JsonWriter& json, std::string_view key, const Eigen::MatrixXd& matrix) {
  json.beginArray(key);
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    std::vector<double> row(matrix.cols());
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) {
      row[c] = matrix(r, c);
    }
    json.numbers(row);
  }
  json.end();
}

void writeJointStates(JsonWriter& json, const SrcManipulator& chain,
                      const std::vector<SrcJointState>& joints) {
  json.beginArray("joints");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const Eigen::Vector2d u = chain.joint(i).rotationVectorOf(joints[i]);
    json.numbers({u.x(), u.y()});
  }
  json.end();
  json.beginArray("joint_quaternions");
  for (const SrcJointState& joint : joints) {
    std::vector<double> pair = wxyz(joint.link);
    const std::vector<double> base = wxyz(joint.base);
    pair.insert(pair.end(), base.begin(), base.end());
    json.numbers(pair);
  }
  json.end();
}

// --- freebot-fk ---------------------------------------------------------------------------------

int runFk(const ParsedOptions& options, std::ostream& out) {
  const bool vectors = options.given("joints");
  const bool quaternions = options.given("joint-quaternions");
  if (vectors == quaternions) {
    throw UsageError("give exactly one of --joints and --joint-quaternions");
  }
  const std::vector<double> radii = radiiFrom(options);
  const std::size_t count = radii.size() - 1;
  const std::vector<std::vector<double>> groups =
      vectors ? jointGroups(options, "joints", 2, count)
              : jointGroups(options, "joint-quaternions", 8, count);
  const SrcManipulator chain(radii);
  const std::vector<SrcJointState> joints =
      vectors ? rotationVectorJoints(chain, groups) : quaternionJoints(chain, groups);
  const std::vector<LinkPose> links = chain.forwardKinematics(joints);
  const Eigen::MatrixXd jacobian = chain.jacobian(joints);

  OutputFile file(options.text("out"));
  JsonWriter json(file.stream());
  json.numbers("radii", radii);
  json.beginArray("links");
  for (const LinkPose& link : links) {
    json.beginObject()
        .numbers("position", xyz(link.position))
        .numbers("orientation", wxyz(link.orientation))
        .numbers("joint_quaternion", wxyz(link.joint))
        .end();
  }
  json.end();
  writeMatrix(json, "jacobian", jacobian);
  json.finish();
  file.commit();
  const LinkPose& end = links.back();
  out << "freebot-fk: " << count << " joints; B_" << count << " at (" << end.position.x() << ", "
      << end.position.y() << ", " << end.position.z() << ") m, orientation (w, x, y, z) ("
      << end.orientation.w() << ", " << end.orientation.x() << ", " << end.orientation.y() << ", "
      << end.orientation.z() << ")\n";
  return kSuccess;
}

const char* const kFkDescription =
    R"(The SRC-joint manipulator of Zong, Liang, Lam 2022: a fixed base sphere B_0 of radius L0
(centre at the origin, axes aligned with the inertial frame) and links B_1 ... B_n of radii
L1 ... Ln, each rolling without slipping or spinning on the one before (the two-DOF SRC joint).
Frames and quaternion order: docs/conventions.md, "FreeBOT".

Joint i is given either by its rotation vector (U_IX, U_IY) [rad] (--joints): the state reached
from the aligned start (all frames coincide, each sphere on top of the previous one) by rolling
straight with the constant joint velocity (U_IX, U_IY) [rad/s] along the tangent-plane axes for
one second, so q_i = exp(U_IX x + U_IY y); or by its full state (--joint-quaternions), the pair
q_{i,1} (B_i relative to the contact plane P_i) then q_{i-1,2} (B_{i-1} relative to P_i), each
W,X,Y,Z (Hamilton, scalar first, unit within 1e-9); q_i = conj(q_{i-1,2}) q_{i,1} (eq 6). With
equal radii every reachable state is a straight roll; with unequal radii the state depends on the
rolling path and only --joint-quaternions can give all of them. Without --radii the chain is
DIR/config/freebot.yaml's (--config DIR), the one the FreeBOT stack's nodes read.

JSON members (numbers with 17 significant digits; SI units, radians):
  radii                  the input radii [m]
  links                  for B_1 ... B_n: position [x, y, z] of the centre [m] and orientation
                         [w, x, y, z] in the inertial frame, joint_quaternion [w, x, y, z] = q_i
                         (B_i relative to B_{i-1})
  jacobian               J_{B_n} of eq 38, 6 rows [v_x, v_y, v_z, w_x, w_y, w_z] of B_n (inertial
                         frame) by 2n columns: joint 1 x, joint 1 y, joint 2 x, ... (joint
                         velocities along the tangent-plane axes of P_i [rad/s])
stdout: one line with B_n's pose.

Exit status: 0 success; 2 usage error (unknown or repeated option, malformed number, fewer than
two radii, a joint list that does not parse, a joint count that is not the number of radii
minus 1, both or neither of --joints and --joint-quaternions); 4 invalid input: one-line error on
stderr and no output file (a radius <= 0, a non-finite number, a quaternion that is not unit
within 1e-9, without --radii an unreadable config/freebot.yaml or a bad value in it).
)";

// --- freebot-ik ---------------------------------------------------------------------------------

int runIk(const ParsedOptions& options, std::ostream& out) {
  const std::vector<double> radii = radiiFrom(options);
  const std::size_t count = radii.size() - 1;
  const std::vector<double> target = options.numberList("target");
  if (target.size() != 3 && target.size() != 7) {
    throw UsageError("--target: '" + options.text("target") + "' has " +
                     std::to_string(target.size()) +
                     " numbers, expected 3 (X,Y,Z) or 7 (X,Y,Z,QW,QX,QY,QZ)");
  }
  IkOptions ik = config::freebotGoalExecutive(freebotConfig(options)).ik;
  ik.mode =
      options.flag("position-only") || target.size() == 3 ? IkMode::PositionOnly : IkMode::FullPose;
  if (options.given("position-tolerance"))
    ik.position_tolerance = options.number("position-tolerance");
  if (options.given("orientation-tolerance"))
    ik.orientation_tolerance = options.number("orientation-tolerance");
  if (options.given("restarts")) ik.restarts = options.integer("restarts");
  const int random_seed = options.integer("random-seed");
  if (random_seed < 0) {
    throw InvalidInput("--random-seed must be >= 0, got " + options.text("random-seed"));
  }
  ik.seed = static_cast<std::uint32_t>(random_seed);
  const std::vector<std::vector<double>> seed_groups = options.given("seed")
                                                           ? jointGroups(options, "seed", 2, count)
                                                           : std::vector<std::vector<double>>{};

  const SrcManipulator chain(radii);
  const std::vector<SrcJointState> seed =
      seed_groups.empty() ? std::vector<SrcJointState>{} : rotationVectorJoints(chain, seed_groups);
  const Eigen::Vector3d position(target[0], target[1], target[2]);
  const Eigen::Quaterniond orientation =
      target.size() == 7 ? Eigen::Quaterniond(target[3], target[4], target[5], target[6])
                         : Eigen::Quaterniond::Identity();
  const IkResult result = freebot::solveIk(chain, position, orientation, seed, ik);

  OutputFile file(options.text("out"));
  JsonWriter json(file.stream());
  json.boolean("success", result.success)
      .text("mode", ik.mode == IkMode::FullPose ? "full-pose" : "position-only")
      .number("position_error", result.position_error)
      .number("orientation_error_deg", result.orientation_error * kDegreesPerRadian);
  writeJointStates(json, chain, result.joints);
  json.number("iterations", result.iterations)
      .number("starts", result.starts)
      .numbers("position", xyz(result.end.position))
      .numbers("orientation", wxyz(result.end.orientation))
      .finish();
  file.commit();
  out << "freebot-ik: " << (result.success ? "reached" : "UNREACHABLE, closest pose found")
      << ": position error " << result.position_error << " m, orientation error "
      << result.orientation_error * kDegreesPerRadian << " deg, " << result.iterations
      << " iterations, " << result.starts << " starts\n";
  return result.success ? kSuccess : kNoSolution;
}

const char* const kIkDescription =
    R"(Inverse kinematics of the SRC-joint manipulator (chain as in `sphere_sim freebot-fk --help`):
joints that put B_n's centre at X,Y,Z [m] and, unless --position-only or only three numbers are
given, its orientation at QW,QX,QY,QZ (inertial frame, Hamilton, scalar first, unit within 1e-9;
ignored in position-only mode). The solver is the adaptive damped least squares of eqs 38-47
(K_p = K_a = 2 I, xi = lambda_max = 0.01 as Table II, the damping fading once the residual is
below 0.01) integrated by rolling the joints, step 2/3 s, each joint at most 1 rad per
iteration, halved until the residual falls; a start ends after 100 iterations or when stuck,
then it restarts from a seeded random configuration, --restarts times at most
(docs/conventions.md, "FreeBOT IK"). Deterministic for given inputs. The chain and the solver's
tolerances, restarts and iterations not given here are DIR/config/freebot.yaml's (--config DIR),
as the FreeBOT stack's freebot_ik node reads them.

JSON members (numbers with 17 significant digits; SI units, radians unless _deg):
  success                true exactly when both errors are within the tolerances
  mode                   "full-pose" or "position-only"
  position_error         |r_target - r_B_n| [m] of the returned joints
  orientation_error_deg  angle between the target and B_n's orientation [deg]; 0 in
                         position-only mode
  joints                 [[u_x, u_y], ...]: each joint's rotation vector (as --joints of
                         freebot-fk): the straight roll that puts the contact point where the
                         solution has it; the whole state exactly when the radii are equal
  joint_quaternions      [[W,X,Y,Z, W,X,Y,Z], ...]: each joint's full state q_{i,1}, q_{i-1,2}
                         (as --joint-quaternions of freebot-fk)
  iterations, starts     iterations over all starts, and 1 + the restarts used
  position, orientation  B_n's pose for the returned joints ([m], [w, x, y, z])
stdout: one line with the verdict and the errors.

Exit status: 0 target reached; 3 not reached (out of reach, or no start converged): the file is
written with success false and the closest pose found; 2 usage error (malformed number, --target
without 3 or 7 numbers, a --seed that does not parse or has the wrong joint count, fewer than two
radii, a non-integer --restarts or --random-seed); 4 invalid input: one-line error and no output
file (a radius <= 0, a non-finite number, a target quaternion that is not unit in full-pose mode,
a tolerance <= 0, --restarts or --random-seed < 0, an unreadable config/freebot.yaml or a bad
value in it).
)";

// --- freebot-wheels -----------------------------------------------------------------------------

int runWheels(const ParsedOptions& options, std::ostream& out) {
  const bool trolley_given = options.given("trolley");
  const bool wheels_given = options.given("wheels");
  if (trolley_given == wheels_given) {
    throw UsageError("give exactly one of --trolley U_F,U_S and --wheels W_R,W_L");
  }
  const bool geometry_given = options.given("wheel-radius") && options.given("wheel-interval") &&
                              options.given("shell-radii");
  // Absent geometry is module 1's trolley of the configured chain (its shell is sphere B_1).
  const std::optional<freebot::FreebotChain> chain =
      geometry_given ? std::nullopt : std::optional(config::freebotChain(freebotConfig(options)));
  const double wheel_radius = options.given("wheel-radius") ? options.number("wheel-radius")
                                                            : chain->trolley(0).wheelRadius();
  const double wheel_interval = options.given("wheel-interval")
                                    ? options.number("wheel-interval")
                                    : chain->trolley(0).wheelInterval();
  const std::vector<double> shell =
      options.given("shell-radii")
          ? options.numberList("shell-radii", 2)
          : std::vector<double>{chain->trolley(0).innerRadius(), chain->trolley(0).outerRadius()};
  const std::vector<double> speeds = options.numberList(trolley_given ? "trolley" : "wheels", 2);
  const freebot::TrolleyDrive drive(wheel_radius, wheel_interval, shell[0], shell[1]);
  freebot::TrolleySpeeds trolley;
  freebot::WheelSpeeds wheels;
  if (trolley_given) {
    trolley = {speeds[0], speeds[1]};
    wheels = drive.wheelSpeeds(trolley);  // eq 65
  } else {
    wheels = {speeds[0], speeds[1]};
    trolley = drive.trolleySpeeds(wheels);  // eq 64
  }
  OutputFile file(options.text("out"));
  JsonWriter json(file.stream());
  json.text("mode", trolley_given ? "trolley-to-wheels" : "wheels-to-trolley")
      .number("u_f", trolley.forward)
      .number("u_s", trolley.steering)
      .number("w_r", wheels.right)
      .number("w_l", wheels.left)
      .number("wheel_contact_radius", drive.wheelContactRadius())
      .finish();
  file.commit();
  out << "freebot-wheels: u_f " << trolley.forward << " m/s, u_s " << trolley.steering
      << " rad/s; w_r " << wheels.right << " rad/s, w_l " << wheels.left << " rad/s\n";
  return kSuccess;
}

const char* const kWheelsDescription =
    R"(The FreeBOT driving trolley (Zong, Liang, Lam 2022, eqs 64, 65 and appendix C): two wheels
of radius R_W, L_W apart, run on the inner surface (radius R_IN) of a shell of outer radius
R_OUT (Table II: 0.005, 0.046, 0.032, 0.034). --trolley gives the forward speed U_F [m/s] (of
the shell's outer surface relative to the trolley) and the steering speed U_S [rad/s]
(counter-clockwise about the outward normal) and computes the wheel speeds (eq 65); --wheels
gives the right and left wheel speeds W_R, W_L [rad/s] and computes U_F, U_S (eq 64). The
geometry not given here is module 1's trolley in DIR/config/freebot.yaml (--config DIR).

JSON members (numbers with 17 significant digits; SI units):
  mode                   "trolley-to-wheels" or "wheels-to-trolley"
  u_f, u_s               trolley forward [m/s] and steering [rad/s] speeds
  w_r, w_l               right and left wheel speeds [rad/s]
  wheel_contact_radius   r' = sqrt(R_IN^2 - (L_W/2)^2) [m] (eq 83)
stdout: one line with the four speeds.

Exit status: 0 success; 2 usage error (malformed number, wrong list length, both or neither of
--trolley and --wheels); 4 invalid input: one-line error and no output file (a length <= 0 or
non-finite, R_IN > R_OUT, L_W >= 2 R_IN: the shell cannot hold the wheels; without all three
of --wheel-radius, --wheel-interval, --shell-radii an unreadable config/freebot.yaml or a bad
value in it).
)";

OptionSpec radiiOption() {
  return optionalOption(
      "radii", "L0,L1,...,Ln",
      "Sphere radii [m], > 0: the fixed base B_0's, then one per link B_1 ... B_n (n >= 1).\n"
      "Default: freebot/radii of config/freebot.yaml, the FreeBOT stack's chain.");
}

}  // namespace

Subcommand freebotFkCommand() {
  Subcommand command;
  command.name = "freebot-fk";
  command.summary =
      "SRC-joint manipulator: link poses and Jacobian J_{B_n} (Zong, Liang, Lam 2022).";
  command.description = kFkDescription;
  command.options = {
      radiiOption(),
      optionalOption(
          "joints", "U1X,U1Y;U2X,U2Y;...",
          "Each joint's rotation vector [rad] along its tangent-plane axes, ';' between joints.\n"
          "Not with --joint-quaternions."),
      optionalOption(
          "joint-quaternions", "W,X,Y,Z,W,X,Y,Z;...",
          "Each joint's full state: q_{i,1} then q_{i-1,2} (scalar first), ';' between joints.\n"
          "Not with --joints."),
      configOption(),
      outOption("JSON file to write (members below)."),
  };
  command.run = runFk;
  return command;
}

Subcommand freebotIkCommand() {
  Subcommand command;
  command.name = "freebot-ik";
  command.summary = "SRC-joint manipulator: inverse kinematics by adaptive damped least squares.";
  command.description = kIkDescription;
  command.options = {
      radiiOption(),
      requiredOption("target", "X,Y,Z[,QW,QX,QY,QZ]",
                     "Target centre of B_n [m] and, for a full pose, "
                     "its orientation (unit quaternion, scalar\n"
                     "first). Three numbers: position only."),
      flagOption("position-only",
                 "Reach the position only; the orientation, if given, is ignored."),
      optionalOption(
          "seed", "U1X,U1Y;U2X,U2Y;...",
          "First start: each joint's rotation vector [rad] (as freebot-fk --joints); default the\n"
          "aligned start."),
      optionalOption("position-tolerance", "M",
                     "Success: position error <= M [m], > 0.\n"
                     "Default: freebot/ik/position_tolerance of config/freebot.yaml (1e-5)."),
      optionalOption("orientation-tolerance", "RAD",
                     "Success: orientation error <= RAD [rad], > 0.\n"
                     "Default: freebot/ik/orientation_tolerance of config/freebot.yaml (1e-4)."),
      optionalOption("restarts", "N",
                     "Random restarts after the first start, integer >= 0.\n"
                     "Default: freebot/ik/restarts of config/freebot.yaml (60)."),
      optionalOption("random-seed", "S",
                     "Seed of the restarts' random configurations, integer >= 0.", "1"),
      configOption(),
      outOption("JSON file to write (members below), also when the target is not reached."),
  };
  command.run = runIk;
  return command;
}

Subcommand freebotWheelsCommand() {
  Subcommand command;
  command.name = "freebot-wheels";
  command.summary = "FreeBOT trolley: wheel speeds <-> forward and steering speeds (eqs 64, 65).";
  command.description = kWheelsDescription;
  command.options = {
      optionalOption(
          "wheel-radius", "R_W",
          "Wheel radius [m], > 0. Default: freebot/trolley/wheel_radius of config/freebot.yaml."),
      optionalOption("wheel-interval", "L_W",
                     "Distance between the wheels [m], > 0 and < 2 R_IN.\n"
                     "Default: freebot/trolley/wheel_interval of config/freebot.yaml."),
      optionalOption("shell-radii", "R_IN,R_OUT",
                     "Inner and outer shell radii [m], 0 < R_IN <= R_OUT. Default: module 1's of\n"
                     "config/freebot.yaml (l_1 - freebot/trolley/shell_thickness, l_1)."),
      optionalOption(
          "trolley", "U_F,U_S",
          "Trolley forward [m/s] and steering [rad/s] speeds -> wheel speeds. Not with --wheels."),
      optionalOption("wheels", "W_R,W_L",
                     "Right and left wheel speeds [rad/s] -> trolley speeds. Not with --trolley."),
      configOption(),
      outOption("JSON file to write (members below)."),
  };
  command.run = runWheels;
  return command;
}

}  // namespace spherical_robots::sphere_sim
