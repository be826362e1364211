// `sphere_sim norma` run as an executable, checked against independent truth: the path of eq 52
// and its error, the initial heading and the cascade's first output worked by hand, energy
// conservation of the unforced robot, the closed-form energy difference of the two variants,
// the logging contract, the slider warning and the exit statuses (DESIGN.md, "sphere_sim").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sphere_sim_process.hpp"

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kColumns = {
    "t",   "theta", "alpha", "phi", "delta", "thetad", "alphad", "phid", "deltad",
    "X",   "Y",     "psi",   "Xd",  "Yd",    "err",    "T",      "F",    "energy"};

using sphere_sim_test::readFile;

/// A run of `sphere_sim norma`: its exit status, stdout and stderr, and the CSV if it wrote one.
struct Result : sphere_sim_test::Process, sphere_sim_test::Csv {};

class SphereSimNormaTest : public sphere_sim_test::SphereSimFixture {
 protected:
  SphereSimNormaTest() : SphereSimFixture("sphere_sim_norma", "run.csv") {}

  /// `sphere_sim norma ARGS --config CONFIG --out DIR/run.csv` (default: the source tree's
  /// urdf/); the CSV read back if it was written.
  Result norma(const std::string& args,
               const std::string& config = SPHERICAL_ROBOTS_SOURCE_DIR) const {
    std::vector<std::string> argv = {"norma"};
    std::istringstream words(args);
    for (std::string word; words >> word;) argv.push_back(word);
    argv.insert(argv.end(), {"--config", config, "--out", out_.string()});
    const sphere_sim_test::Process process = run(argv);
    return {process, fs::exists(out_) ? sphere_sim_test::readCsv(out_) : sphere_sim_test::Csv{}};
  }

  bool csvWritten() const { return fs::exists(out_); }
};

TEST_F(SphereSimNormaTest, PaperClosedLoopRowsFollowEq52) {
  const Result r = norma("--duration 20 --log-rate 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.header, kColumns);
  ASSERT_EQ(r.rows.size(), 41u);
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const double t = r.at(i, "t");
    EXPECT_NEAR(t, 0.5 * i, 1e-12);
    EXPECT_NEAR(r.at(i, "Xd"), 2 * std::sin(0.01 * t), 1e-12);
    EXPECT_NEAR(r.at(i, "Yd"), 1.5 * std::sin(0.02 * t), 1e-12);
    EXPECT_NEAR(r.at(i, "err"),
                std::hypot(r.at(i, "X") - r.at(i, "Xd"), r.at(i, "Y") - r.at(i, "Yd")), 1e-12);
  }
  // t = 0: at rest on the path, heading along (0.02, 0.03) m/s; θ̇_d = |v_d| / R (eq 51), and
  // T = PID2 kp · PID1 kp · θ̇_d = 10 · sqrt(0.0013) / 0.2.
  for (const char* zero : {"theta", "alpha", "phi", "delta", "thetad", "X", "Y", "err", "F"}) {
    EXPECT_EQ(r.at(0, zero), 0.0) << zero;
  }
  EXPECT_NEAR(r.at(0, "psi"), std::atan2(0.03, 0.02), 1e-15);
  EXPECT_NEAR(r.at(0, "T"), 10.0 * std::sqrt(0.0013) / 0.2, 1e-12);
  // It rolls forward along the path.
  EXPECT_GT(r.at(40, "X"), 0.3);
  EXPECT_GT(r.at(40, "Y"), 0.4);
  EXPECT_NE(r.out.find("RMS |e|"), std::string::npos) << r.out;
}

// Unforced, the total energy is conserved at tight tolerances; the closed-loop columns hold 0.
TEST_F(SphereSimNormaTest, OpenLoopConservesEnergy) {
  const Result r = norma(
      "--open-loop --q0 0,0.6,-0.1,0.02 --qd0 1,0,0.3,0 --duration 0.3 --log-rate 10 "
      "--rtol 1e-11 --atol 1e-12");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(r.rows.size(), 4u);
  const double e0 = r.at(0, "energy");
  ASSERT_GT(e0, 0.1);
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    EXPECT_NEAR(r.at(i, "energy"), e0, 1e-9 * e0);
    for (const char* zero : {"Xd", "Yd", "err", "T", "F"}) EXPECT_EQ(r.at(i, zero), 0.0);
  }
  EXPECT_NE(r.at(3, "theta"), 0.0);
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// The appendix's M11 lacks ½ I_Sp^z (θ̇ S_φ)², I_Sp^z = I_Shl + I_Shf^x C_φ² (eqs 37-40):
// with θ̇ = 1, φ = −0.5 the energies at t = 0 differ by exactly that.
TEST_F(SphereSimNormaTest, VariantsDifferBySphereYawEnergy) {
  const std::string args = "--open-loop --q0 0,0.2,-0.5,0 --qd0 1,0,0,0 --duration 0";
  const Result text = norma(args + " --variant text");
  const Result appendix = norma(args + " --variant appendix");
  ASSERT_EQ(text.status, 0) << text.err;
  ASSERT_EQ(appendix.status, 0) << appendix.err;
  ASSERT_EQ(text.rows.size(), 1u);
  const double i_z = 2.0 / 3.0 * 2.5 * 0.04 + 1.0 / 3.0 * 0.5 * 0.04 * std::pow(std::cos(0.5), 2);
  EXPECT_NEAR(text.at(0, "energy") - appendix.at(0, "energy"),
              0.5 * i_z * std::pow(std::sin(0.5), 2), 1e-15);
}

// The free slider runs off the shaft (|δ0 + δ| > R): one warning, and the run completes.
TEST_F(SphereSimNormaTest, WarnsOnceWhenSliderLeavesShaft) {
  const Result r = norma("--open-loop --q0 0,0.6,-0.1,0.02 --qd0 1,0,0,0 --duration 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.rows.size(), 201u);
  std::size_t warnings = 0;
  for (std::size_t at = r.err.find("warning"); at != std::string::npos;
       at = r.err.find("warning", at + 1)) {
    ++warnings;
  }
  EXPECT_EQ(warnings, 1u) << r.err;
  double beyond = 0.0;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    beyond = std::max(beyond, std::abs(0.1 + r.at(i, "delta")) - 0.2);
  }
  EXPECT_GT(beyond, 0.0);
}

// --loop sampled: a row per 1 ms step from the first, t since the first step; at rest on the path
// at the first, where the paper's first command T = 10 sqrt(0.0013) / 0.2 (as in the continuous
// run) is applied; clamped at --max-torque; and with --state-timeout below the step every effort
// is stale at the plant, so the robot stays exactly at rest.
TEST_F(SphereSimNormaTest, SampledLoopRunsTheStacksSteps) {
  const Result r = norma("--loop sampled --duration 0.01 --log-rate 1000");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.header, kColumns);
  ASSERT_EQ(r.rows.size(), 11u);
  for (std::size_t i = 0; i < r.rows.size(); ++i) EXPECT_NEAR(r.at(i, "t"), 0.001 * i, 1e-15);
  for (const char* zero : {"theta", "alpha", "phi", "delta", "thetad", "X", "Y", "err", "F"}) {
    EXPECT_EQ(r.at(0, zero), 0.0) << zero;
  }
  EXPECT_NEAR(r.at(0, "psi"), std::atan2(0.03, 0.02), 1e-15);
  EXPECT_NEAR(r.at(0, "T"), 10.0 * std::sqrt(0.0013) / 0.2, 1e-12);
  EXPECT_GT(r.at(10, "X"), 0.0);
  EXPECT_NE(r.out.find("sampled loop"), std::string::npos) << r.out;

  const Result clamped = norma("--loop sampled --duration 0.01 --log-rate 1000 --max-torque 1");
  ASSERT_EQ(clamped.status, 0) << clamped.err;
  EXPECT_EQ(clamped.at(0, "T"), 1.0);

  const Result stale = norma("--loop sampled --duration 1 --log-rate 100 --state-timeout 0.0005");
  ASSERT_EQ(stale.status, 0) << stale.err;
  ASSERT_EQ(stale.rows.size(), 101u);
  for (const char* zero : {"theta", "alpha", "phi", "delta", "X", "Y"}) {
    EXPECT_EQ(stale.at(100, zero), 0.0) << zero;
  }

  const Result slow = norma("--loop sampled --duration 2");  // the closed loop's 1 Hz rows
  ASSERT_EQ(slow.status, 0) << slow.err;
  ASSERT_EQ(slow.rows.size(), 3u);
  EXPECT_EQ(slow.at(2, "t"), 2.0);
}

TEST_F(SphereSimNormaTest, BadInputExitsWithoutOutput) {
  const std::vector<std::pair<std::string, int>> cases = {
      {"--q0 0,0,0,0", 2},                                     // closed loop takes no state
      {"--open-loop --q0 0,0,0,0", 2},                         // --qd0 missing
      {"--open-loop --q0 0,0,0 --qd0 0,0,0,0", 2},             // three values
      {"--open-loop --q0 0,0,0,0 --qd0 0,0,0,0 --controller paper", 2},
      {"--controller pid", 2},
      {"--variant book", 2},
      {"--rtol x", 2},
      {"--rtol -1e-6", 4},
      {"--atol 0", 4},
      {"--duration -1", 4},
      {"--log-rate 0", 4},
      {"--open-loop --q0 0,nan,0,0 --qd0 0,0,0,0", 4},
      {"--open-loop --q0 0,0,0,0 --qd0 inf,0,0,0", 4},
      {"--loop closed", 2},
      {"--loop sampled --rtol 1e-6", 2},                      // the adaptive integrator's
      {"--loop sampled --atol 1e-9", 2},
      {"--max-torque 5", 2},                                   // the sampled loop's
      {"--loop continuous --state-timeout 0.1", 2},
      {"--loop sampled --open-loop --q0 0,0,0,0 --qd0 0,0,0,0", 2},
      {"--open-loop --q0 0,0,0,0 --qd0 0,0,0,0 --max-force 5", 2},
      {"--loop sampled --log-rate 3", 4},                      // rows off whole 1 ms steps
      {"--loop sampled --log-rate 2000", 4},
      {"--loop sampled --log-rate 0", 4},
      {"--loop sampled --max-torque 0", 4},
      {"--loop sampled --max-force -200", 4},
      {"--loop sampled --command-timeout -1", 4},
      {"--loop sampled --state-timeout nan", 4},
      {"--loop sampled --duration -1", 4},
      {"--loop sampled --duration 1e300", 4},                 // more steps than a run allows
  };
  for (const auto& [args, status] : cases) {
    const Result r = norma(args);
    EXPECT_EQ(r.status, status) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(csvWritten()) << args;
  }
}

// The robot comes from DIR/urdf/norma.urdf: a longer pendulum (L = 0.3 m) changes the energy
// of a swinging pendulum by exactly what eq 20 says, m_P g (L − L') C_β at rest.
TEST_F(SphereSimNormaTest, ReadsRobotFromUrdf) {
  const fs::path config = dir_ / "config_dir";
  fs::create_directories(config / "urdf");
  fs::create_directories(config / "config");
  std::string xml = readFile(fs::path(SPHERICAL_ROBOTS_SOURCE_DIR) / "urdf" / "norma.urdf");
  xml.replace(xml.find("<origin xyz=\"0 0 -0.15\"/>\n      <mass"), 25,
              "<origin xyz=\"0 0 -0.30\"/>");
  std::ofstream(config / "urdf" / "norma.urdf") << xml;
  const std::string args = "--open-loop --q0 0,0.5,0,0 --qd0 0,0,0,0 --duration 0";
  const Result shipped = norma(args);
  const Result longer = norma(args, config.string());
  ASSERT_EQ(shipped.status, 0) << shipped.err;
  ASSERT_EQ(longer.status, 0) << longer.err;
  // E^p shifted to 0 at q = 0: m_P g L (1 − C_β).
  EXPECT_NEAR(shipped.at(0, "energy"), 0.5 * 9.81 * 0.15 * (1 - std::cos(0.5)), 1e-14);
  EXPECT_NEAR(longer.at(0, "energy"), 0.5 * 9.81 * 0.30 * (1 - std::cos(0.5)), 1e-14);
  fs::remove(config / "urdf" / "norma.urdf");
  fs::remove(out_);
  const Result missing = norma(args, config.string());
  EXPECT_EQ(missing.status, 4);
  EXPECT_NE(missing.err.find("norma.urdf"), std::string::npos) << missing.err;
  EXPECT_FALSE(csvWritten());
}

TEST_F(SphereSimNormaTest, HelpNamesColumnsAndDefaults) {
  const Result r = norma("--help");
  EXPECT_EQ(r.status, 0);
  for (const std::string& column : kColumns) {
    EXPECT_NE(r.out.find(column), std::string::npos) << column;
  }
  EXPECT_NE(r.out.find("0.001"), std::string::npos);  // --rtol default
  EXPECT_NE(r.out.find("1e-06"), std::string::npos);  // --atol default
  for (const char* sampled : {"--loop", "sampled", "max_torque", "command_timeout",
                              "state_timeout", "bit for bit"}) {
    EXPECT_NE(r.out.find(sampled), std::string::npos) << sampled;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
