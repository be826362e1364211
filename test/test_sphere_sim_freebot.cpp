// `sphere_sim freebot-fk`, `freebot-ik` and `freebot-wheels`, run as the built executable, against
// independent truth: the closed form of straight rolls and finite differences of rolling for
// the forward kinematics and J_{B_n}, a round trip IK → FK through the files, targets out of
// reach, the appendix-C wheel geometry, the defaults from config/freebot.yaml (the stack's file),
// and the exit statuses 2, 3 and 4 of DESIGN.md.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sphere_sim_process.hpp"

namespace {

namespace fs = std::filesystem;
using boost::property_tree::ptree;
using sphere_sim_test::Process;

Eigen::Quaterniond angleAxis(const Eigen::Vector3d& v) {
  if (v.norm() == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(v.norm(), v.normalized()));
}

std::string text17(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

std::string joinQuaternionPairs(
    const std::vector<std::pair<Eigen::Quaterniond, Eigen::Quaterniond>>& joints) {
  std::string list;
  for (const auto& [link, base] : joints) {
    if (!list.empty()) list += ";";
    for (const Eigen::Quaterniond& q : {link, base}) {
      for (double c : {q.w(), q.x(), q.y(), q.z()}) {
        list += (list.empty() || list.back() == ';' ? "" : ",") + text17(c);
      }
    }
  }
  return list;
}

std::vector<double> numbers(const ptree& array) {
  std::vector<double> values;
  for (const auto& item : array) values.push_back(item.second.get_value<double>());
  return values;
}

std::vector<std::vector<double>> rows(const ptree& array) {
  std::vector<std::vector<double>> values;
  for (const auto& item : array) values.push_back(numbers(item.second));
  return values;
}

Eigen::Vector3d vector3(const ptree& array) {
  const std::vector<double> v = numbers(array);
  EXPECT_EQ(v.size(), 3u);
  return v.size() == 3 ? Eigen::Vector3d(v[0], v[1], v[2]) : Eigen::Vector3d::Zero();
}

Eigen::Quaterniond quaternion(const ptree& array) {
  const std::vector<double> v = numbers(array);
  EXPECT_EQ(v.size(), 4u);
  return v.size() == 4 ? Eigen::Quaterniond(v[0], v[1], v[2], v[3]) : Eigen::Quaterniond();
}

class FreebotCliTest : public sphere_sim_test::SphereSimFixture {
 protected:
  FreebotCliTest() : SphereSimFixture("sphere_sim_freebot", "out.json") {}

  /// `sphere_sim args... --out out.json` in the test's directory, without an old out.json.
  Process run(std::vector<std::string> args) const {
    fs::remove(out_);  // a file from an earlier run must not count
    args.push_back("--out");
    args.push_back(out_.string());
    return SphereSimFixture::run(args);
  }

  ptree json() const {
    ptree tree;
    boost::property_tree::read_json(out_.string(), tree);
    return tree;
  }

  /// Exit status `status`, a one-line message naming `needle` on stderr, no output file.
  void expectRejected(const std::vector<std::string>& args, int status, const std::string& needle) {
    const Process process = run(args);
    EXPECT_EQ(process.status, status) << process.err;
    EXPECT_NE(process.err.find(needle), std::string::npos) << process.err;
    EXPECT_FALSE(fs::exists(out_)) << args.front();
    if (status == 4) {
      EXPECT_EQ(std::count(process.err.begin(), process.err.end(), '\n'), 1) << process.err;
    }
  }
};

// Radii of the fixed base and two links, joints as rotation vectors.
const std::vector<double> kRadii = {0.034, 0.03, 0.04};
const Eigen::Vector2d kU1(0.4, -0.7);
const Eigen::Vector2d kU2(-1.1, 0.3);
const std::string kRadiiText = "0.034,0.03,0.04";
const std::string kJointsText = "0.4,-0.7;-1.1,0.3";

TEST_F(FreebotCliTest, ForwardKinematicsOfStraightRolls) {
  const Process process = run({"freebot-fk", "--radii", kRadiiText, "--joints", kJointsText});
  ASSERT_EQ(process.status, 0) << process.err;
  const ptree out = json();
  // Closed form: B_i turns by exp(u_i) relative to B_{i-1}; its centre is at
  // (l_{i-1} + l_i) exp(l_i/(l_{i-1} + l_i) u_i) z in B_{i-1}'s frame.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  const Eigen::Vector2d u[] = {kU1, kU2};
  int i = 0;
  for (const auto& link : out.get_child("links")) {
    const double sum = kRadii[i] + kRadii[i + 1];
    const Eigen::Vector3d rotation(u[i].x(), u[i].y(), 0.0);
    position += orientation *
                (sum * (angleAxis(kRadii[i + 1] / sum * rotation) * Eigen::Vector3d::UnitZ()));
    orientation = orientation * angleAxis(rotation);
    EXPECT_LE((vector3(link.second.get_child("position")) - position).norm(), 1e-15);
    EXPECT_LE(quaternion(link.second.get_child("orientation")).angularDistance(orientation), 1e-13);
    EXPECT_LE(
        quaternion(link.second.get_child("joint_quaternion")).angularDistance(angleAxis(rotation)),
        1e-13);
    ++i;
  }
  EXPECT_EQ(i, 2);
  const auto jacobian = rows(out.get_child("jacobian"));
  ASSERT_EQ(jacobian.size(), 6u);
  for (const auto& row : jacobian) EXPECT_EQ(row.size(), 4u);
}

TEST_F(FreebotCliTest, JointQuaternionsGiveTheFullStateAndTheJacobianIsTheirDerivative) {
  // The straight rolls as quaternion pairs: B_i turns by l_{i-1}/L u and B_{i-1} by −l_i/L u
  // relative to P_i.
  std::vector<std::pair<Eigen::Quaterniond, Eigen::Quaterniond>> joints;
  const Eigen::Vector2d u[] = {kU1, kU2};
  for (int i = 0; i < 2; ++i) {
    const double sum = kRadii[i] + kRadii[i + 1];
    const Eigen::Vector3d rotation(u[i].x(), u[i].y(), 0.0);
    joints.emplace_back(angleAxis(kRadii[i] / sum * rotation),
                        angleAxis(-kRadii[i + 1] / sum * rotation));
  }
  ASSERT_EQ(run({"freebot-fk", "--radii", kRadiiText, "--joints", kJointsText}).status, 0);
  const ptree by_vectors = json();
  const Process process = run(
      {"freebot-fk", "--radii", kRadiiText, "--joint-quaternions", joinQuaternionPairs(joints)});
  ASSERT_EQ(process.status, 0) << process.err;
  const ptree by_quaternions = json();
  const Eigen::Vector3d end =
      vector3(by_quaternions.get_child("links").back().second.get_child("position"));
  EXPECT_LE(
      (vector3(by_vectors.get_child("links").back().second.get_child("position")) - end).norm(),
      1e-15);
  // Each column: roll joint i by ±ε about P_i's axis and difference B_n's pose.
  const auto jacobian = rows(by_quaternions.get_child("jacobian"));
  const double eps = 1e-6;
  for (int i = 0; i < 2; ++i) {
    const double sum = kRadii[i] + kRadii[i + 1];
    for (int axis = 0; axis < 2; ++axis) {
      std::vector<Eigen::Vector3d> positions;
      std::vector<Eigen::Quaterniond> orientations;
      for (double s : {eps, -eps}) {
        auto rolled = joints;
        const Eigen::Vector3d e = s * Eigen::Vector3d::Unit(axis);
        rolled[i].first = angleAxis(kRadii[i] / sum * e) * joints[i].first;
        rolled[i].second = angleAxis(-kRadii[i + 1] / sum * e) * joints[i].second;
        ASSERT_EQ(run({"freebot-fk", "--radii", kRadiiText, "--joint-quaternions",
                       joinQuaternionPairs(rolled)})
                      .status,
                  0);
        const ptree out = json();
        const ptree& last = out.get_child("links").back().second;
        positions.push_back(vector3(last.get_child("position")));
        orientations.push_back(quaternion(last.get_child("orientation")));
      }
      const Eigen::Vector3d v = (positions[0] - positions[1]) / (2 * eps);
      const Eigen::AngleAxisd turn(orientations[0] * orientations[1].conjugate());
      const Eigen::Vector3d w = turn.angle() * turn.axis() / (2 * eps);
      const int column = 2 * i + axis;
      for (int r = 0; r < 3; ++r) {
        EXPECT_NEAR(jacobian[r][column], v[r], 1e-8) << "v row " << r << " column " << column;
        EXPECT_NEAR(jacobian[3 + r][column], w[r], 1e-8) << "w row " << r << " column " << column;
      }
    }
  }
}

TEST_F(FreebotCliTest, InverseKinematicsRoundTripsThroughForwardKinematics) {
  // A reachable target: B_3's pose for some joints (made by freebot-fk).
  const std::string radii = "0.034,0.03,0.04,0.025";
  ASSERT_EQ(run({"freebot-fk", "--radii", radii, "--joints", "0.4,-0.7;-1.1,0.3;0.5,0.9"}).status,
            0);
  const ptree fk = json();
  const ptree& last = fk.get_child("links").back().second;
  const Eigen::Vector3d position = vector3(last.get_child("position"));
  const Eigen::Quaterniond orientation = quaternion(last.get_child("orientation"));
  std::string target;
  for (double c : {position.x(), position.y(), position.z(), orientation.w(), orientation.x(),
                   orientation.y(), orientation.z()}) {
    target += (target.empty() ? "" : ",") + text17(c);
  }
  const Process process = run({"freebot-ik", "--radii", radii, "--target", target});
  ASSERT_EQ(process.status, 0) << process.err << process.out;
  const ptree ik = json();
  EXPECT_EQ(ik.get<std::string>("success"), "true");
  EXPECT_LE(ik.get<double>("position_error"), 1e-5);
  EXPECT_LE(ik.get<double>("orientation_error_deg"), 1e-4 * 180 / M_PI);
  EXPECT_EQ(rows(ik.get_child("joints")).size(), 3u);
  // The full states fed back to freebot-fk put B_3 at the target.
  std::string states;
  for (const auto& pair : rows(ik.get_child("joint_quaternions"))) {
    ASSERT_EQ(pair.size(), 8u);
    for (double c : pair) states += (states.empty() || states.back() == ';' ? "" : ",") + text17(c);
    states += ";";
  }
  states.pop_back();
  ASSERT_EQ(run({"freebot-fk", "--radii", radii, "--joint-quaternions", states}).status, 0);
  const ptree back = json();
  const ptree& reached = back.get_child("links").back().second;
  EXPECT_LE((vector3(reached.get_child("position")) - position).norm(), 1e-5);
  EXPECT_LE(quaternion(reached.get_child("orientation")).angularDistance(orientation), 1e-4);
}

TEST_F(FreebotCliTest, PositionOnlyAndOutOfReach) {
  const std::string radii = "0.034,0.034,0.034,0.034";  // reach 0.204 m
  Process process = run({"freebot-ik", "--radii", radii, "--target", "0.01,-0.02,0.19"});
  ASSERT_EQ(process.status, 0) << process.err;
  EXPECT_EQ(json().get<std::string>("mode"), "position-only");
  EXPECT_LE((vector3(json().get_child("position")) - Eigen::Vector3d(0.01, -0.02, 0.19)).norm(),
            1e-5);
  // Out of reach: exit 3, the file says so, and holds the closest pose (stretched chain).
  process = run({"freebot-ik", "--radii", radii, "--target", "0.1,0.2,0.1", "--restarts", "2"});
  EXPECT_EQ(process.status, 3) << process.err;
  const ptree out = json();
  EXPECT_EQ(out.get<std::string>("success"), "false");
  const double distance = Eigen::Vector3d(0.1, 0.2, 0.1).norm();
  EXPECT_NEAR(out.get<double>("position_error"), distance - 0.204, 1e-5);
  EXPECT_NEAR(vector3(out.get_child("position")).norm(), 0.204, 1e-5);
  EXPECT_NE(process.out.find("UNREACHABLE"), std::string::npos) << process.out;
}

TEST_F(FreebotCliTest, WheelSpeedsOfTableIIGeometry) {
  const std::vector<std::string> geometry = {"freebot-wheels",   "--wheel-radius", "0.005",
                                             "--wheel-interval", "0.046",          "--shell-radii",
                                             "0.032,0.034"};
  auto args = geometry;
  args.insert(args.end(), {"--trolley", "0.01,-0.5"});
  ASSERT_EQ(run(args).status, 0);
  const ptree out = json();
  // Appendix C: mean wheel speed r' u_f / (r_out r_w), half difference (l_w/2) u_s / r_w.
  const double r_prime = std::sqrt(0.032 * 0.032 - 0.023 * 0.023);
  const double mean = r_prime * 0.01 / (0.034 * 0.005);
  const double half_difference = 0.023 * -0.5 / 0.005;
  EXPECT_NEAR(out.get<double>("w_r"), mean + half_difference, 1e-12);
  EXPECT_NEAR(out.get<double>("w_l"), mean - half_difference, 1e-12);
  EXPECT_NEAR(out.get<double>("u_f"), 0.01, 1e-17);
  args = geometry;
  args.insert(args.end(),
              {"--wheels", text17(out.get<double>("w_r")) + "," + text17(out.get<double>("w_l"))});
  ASSERT_EQ(run(args).status, 0);
  EXPECT_NEAR(json().get<double>("u_f"), 0.01, 1e-16);
  EXPECT_NEAR(json().get<double>("u_s"), -0.5, 1e-14);
}

TEST_F(FreebotCliTest, ChainSolverAndTrolleyDefaultToTheStacksConfiguration) {
  // Without --config: the shipped config/freebot.yaml, the stack's four Table II modules and the
  // solver's documented defaults, to the last digit of the output.
  const auto output = [&](const std::vector<std::string>& args) {
    EXPECT_EQ(run(args).status, 0) << args.front();
    return sphere_sim_test::readFile(out_);
  };
  const std::string target = "0.05,0.12,0.15";  // freebot_stack.test's position-only goal
  EXPECT_EQ(output({"freebot-ik", "--target", target}),
            output({"freebot-ik", "--target", target, "--radii", "0.034,0.034,0.034,0.034,0.034",
                    "--position-tolerance", "1e-5", "--orientation-tolerance", "1e-4",
                    "--restarts", "60"}));
  EXPECT_EQ(output({"freebot-wheels", "--trolley", "0.01,-0.5"}),
            output({"freebot-wheels", "--trolley", "0.01,-0.5", "--wheel-radius", "0.005",
                    "--wheel-interval", "0.046", "--shell-radii", "0.032,0.034"}));
  // --config DIR: DIR/config/freebot.yaml.
  fs::create_directories(dir_ / "share" / "config");
  std::ofstream(dir_ / "share" / "config" / "freebot.yaml")
      << "freebot:\n  radii: [" << kRadiiText << "]\n  ik: {position_tolerance: 2.0e-5}\n";
  const std::string share = (dir_ / "share").string();
  EXPECT_EQ(output({"freebot-fk", "--config", share, "--joints", kJointsText}),
            output({"freebot-fk", "--radii", kRadiiText, "--joints", kJointsText}));
  EXPECT_EQ(output({"freebot-ik", "--config", share, "--target", "0.02,0.03,0.06"}),
            output({"freebot-ik", "--radii", kRadiiText, "--target", "0.02,0.03,0.06",
                    "--position-tolerance", "2e-5"}));
  std::ofstream(dir_ / "share" / "config" / "freebot.yaml")
      << "freebot: {radii: [0.034, 0.034], ik: {restarts: -1}}\n";
  expectRejected({"freebot-ik", "--config", share, "--target", "0,0,0.1"}, 4,
                 "freebot/ik/restarts");
  expectRejected({"freebot-fk", "--config", (dir_ / "nowhere").string(), "--joints", "0,0"}, 4,
                 "freebot.yaml");
}

TEST_F(FreebotCliTest, UsageErrorsExitTwo) {
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joints", "0.1,0.2;0.3"}, 2, "--joints");
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joints", "0.1,0.2;0.3,x"}, 2, "--joints");
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joints", "0.1,0.2"}, 2, "3 radii");
  expectRejected({"freebot-fk", "--radii", kRadiiText}, 2, "--joint-quaternions");
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joints", kJointsText,
                  "--joint-quaternions", "1,0,0,0,1,0,0,0;1,0,0,0,1,0,0,0"},
                 2, "exactly one");
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joint-quaternions", "1,0,0,0;1,0,0,0"}, 2,
                 "--joint-quaternions");
  expectRejected({"freebot-fk", "--radii", "0.034", "--joints", "0,0"}, 2, "--radii");
  expectRejected({"freebot-ik", "--radii", kRadiiText, "--target", "0,0,0.1,1,0"}, 2, "--target");
  expectRejected({"freebot-ik", "--radii", kRadiiText, "--target", "0,0,0.1", "--seed", "0,0"}, 2,
                 "--seed");
  expectRejected({"freebot-ik", "--radii", kRadiiText, "--target", "0,0,0.1", "--restarts", "1.5"},
                 2, "--restarts");
  expectRejected({"freebot-wheels", "--wheel-radius", "0.005", "--wheel-interval", "0.046",
                  "--shell-radii", "0.032,0.034", "--trolley", "1,1", "--wheels", "1,1"},
                 2, "exactly one");
  expectRejected({"freebot-wheels", "--wheel-radius", "0.005", "--wheel-interval", "0.046",
                  "--shell-radii", "0.032", "--trolley", "1,1"},
                 2, "--shell-radii");
}

TEST_F(FreebotCliTest, InvalidInputExitsFourWithoutOutput) {
  expectRejected({"freebot-fk", "--radii", "0.034,0,0.034", "--joints", "0,0;0,0"}, 4, "l_i");
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joints", "0,nan;0,0"}, 4, "--joints");
  expectRejected({"freebot-fk", "--radii", kRadiiText, "--joint-quaternions",
                  "1,0,0,0,1,0,0,0;1,1e-4,0,0,1,0,0,0"},  // |q| − 1 = 5e-9
                 4, "joint 2 q_{i,1}");
  expectRejected({"freebot-ik", "--radii", kRadiiText, "--target", "0,0,0.1,1,0.001,0,0"}, 4,
                 "target orientation");
  expectRejected(
      {"freebot-ik", "--radii", kRadiiText, "--target", "0,0,0.1", "--position-tolerance", "0"}, 4,
      "position tolerance");
  expectRejected({"freebot-ik", "--radii", "-0.034,0.03,0.04", "--target", "0,0,0.1"}, 4,
                 "l_{i-1}");
  expectRejected({"freebot-wheels", "--wheel-radius", "0.005", "--wheel-interval", "0.064",
                  "--shell-radii", "0.032,0.034", "--trolley", "1,1"},
                 4, "wheel interval");
  expectRejected({"freebot-wheels", "--wheel-radius", "0.005", "--wheel-interval", "0.046",
                  "--shell-radii", "0.032,0.034", "--wheels", "inf,1"},
                 4, "--wheels");
}

TEST_F(FreebotCliTest, HelpNamesEveryOption) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"freebot-fk", {"--radii", "--joints", "--joint-quaternions", "--config", "--out"}},
      {"freebot-ik",
       {"--radii", "--target", "--position-only", "--seed", "--position-tolerance",
        "--orientation-tolerance", "--restarts", "--random-seed", "--config", "--out"}},
      {"freebot-wheels",
       {"--wheel-radius", "--wheel-interval", "--shell-radii", "--trolley", "--wheels", "--config",
        "--out"}}};
  for (const auto& [name, options] : commands) {
    const Process help = SphereSimFixture::run({name, "--help"});
    EXPECT_EQ(help.status, 0);
    for (const std::string& option : options) {
      EXPECT_NE(help.out.find(option), std::string::npos) << name << " " << option;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
