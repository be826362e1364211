// sphere_sim's command-line contract (DESIGN.md, "sphere_sim") and the terrain subcommand's CSV,
// checked by running the built executable against independent truth: the closed forms of the
// surface (eq 59) and the paths, and the geometry every row must satisfy. The roller
// subcommand's JSON is checked against the published numbers of Kimura et al. 2019.
// The option parser and JSON writer shared by all subcommands are also tested in-process.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sphere_sim_cli.hpp"
#include "sphere_sim_process.hpp"

namespace {

namespace fs = std::filesystem;
namespace cli = spherical_robots::sphere_sim;

constexpr double kRadius = 0.2;          // urdf/terrain_robot.urdf shell sphere [m]
constexpr double kAmplitude = 0.2;       // config/terrain.yaml cosine a [m]
constexpr double kFrequency = 2.0;       // cosine w [rad/m]
constexpr double kCircleRadius = 2.0;    // [m]
constexpr double kCircleRate = 0.05;     // [rad/s]
constexpr double kDiamondHalf = 2.0;     // [m]
constexpr double kDiamondSpeed = 0.1;    // [m/s]
constexpr double kTiltLimit = M_PI / 3;  // RS |phi| limit [rad]
constexpr double kTight = 1e-12;         // closed forms vs. full-precision output

const std::vector<std::string> kRequiredColumns = {"t",  "x0",     "y0",   "z0",  "xd", "yd",
                                                   "zd", "e_norm", "zeta", "psi", "phi"};

double surfaceHeight(double x, double y) {
  return kAmplitude * (std::cos(kFrequency * x) + std::cos(kFrequency * y) - 2.0);
}

/// word occurs in text with no letter, digit or '_' on either side.
bool mentionsWord(const std::string& text, const std::string& word) {
  const auto isWordChar = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || !isWordChar(text[at - 1]);
    const bool ends = at + word.size() == text.size() || !isWordChar(text[at + word.size()]);
    if (starts && ends) return true;
  }
  return false;
}

using sphere_sim_test::Process;
using sphere_sim_test::readFile;

using sphere_sim_test::Csv;
using sphere_sim_test::readCsv;

class SphereSimTest : public sphere_sim_test::SphereSimFixture {
 protected:
  SphereSimTest() : SphereSimFixture("sphere_sim_test", "run.csv") {}

  /// `sphere_sim terrain` with the source tree's config and urdf, writing out_.
  Process terrain(const std::vector<std::string>& args) const {
    std::vector<std::string> full = {"terrain", "--config", SPHERICAL_ROBOTS_SOURCE_DIR, "--out",
                                     out_.string()};
    full.insert(full.end(), args.begin(), args.end());
    return run(full);
  }

  /// Only the captured stdout/stderr may be in the directory: no output, no partial file.
  void expectNoOutputFiles() const {
    for (const auto& entry : fs::directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name == "stdout.txt" || name == "stderr.txt") << "left behind: " << name;
    }
  }
};

// --- exit statuses -----------------------------------------------------------------------------

TEST_F(SphereSimTest, UsageErrorsExitTwoWithUsageAndNoOutput) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--robot", "3R", "--path", "circle", "--speed", "1"}, "--speed"},
      {{"--robot", "XX", "--path", "circle"}, "XX"},
      {{"--robot", "3R", "--path", "square"}, "square"},
      {{"--robot", "3R", "--path", "circle", "--model", "slipping"}, "slipping"},
      {{"--robot", "3R", "--path", "circle", "--law", "fast"}, "--law"},
      {{"--robot", "3R", "--path", "circle", "--dt", "0.0x5"}, "0.0x5"},
      {{"--robot", "3R", "--path", "circle", "--duration", "ten"}, "ten"},
      {{"--robot", "3R", "--path", "circle", "--duration", ""}, "--duration"},
      {{"--path", "circle"}, "--robot"},
      {{"--robot", "3R", "--path", "circle", "--dt"}, "--dt"},
      {{"--robot", "3R", "--path", "circle", "--dt", "--duration", "5"}, "--dt"},
      {{"--robot", "3R", "--path", "circle", "--dt", "0.01", "--dt", "0.02"}, "--dt"},
      {{"--robot", "3R", "--path", "circle", "stray"}, "stray"},
  };
  for (const auto& [args, culprit] : cases) {
    const Process process = terrain(args);
    EXPECT_EQ(process.status, cli::kUsageError) << culprit << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    EXPECT_NE(process.err.find("usage: sphere_sim terrain"), std::string::npos) << process.err;
    expectNoOutputFiles();
  }
}

TEST_F(SphereSimTest, MissingOutIsAUsageError) {
  const Process process = run(
      {"terrain", "--robot", "3R", "--path", "circle", "--config", SPHERICAL_ROBOTS_SOURCE_DIR});
  EXPECT_EQ(process.status, cli::kUsageError);
  EXPECT_NE(process.err.find("--out"), std::string::npos) << process.err;
}

TEST_F(SphereSimTest, UnknownOrMissingSubcommandIsAUsageError) {
  EXPECT_EQ(run({"teleport", "--out", out_.string()}).status, cli::kUsageError);
  const Process bare = run({});
  EXPECT_EQ(bare.status, cli::kUsageError);
  EXPECT_NE(bare.err.find("terrain"), std::string::npos);
  // The contract checker treats a non-zero `SUBCOMMAND --help` as "not offered".
  EXPECT_NE(run({"teleport", "--help"}).status, 0);
}

TEST_F(SphereSimTest, InvalidInputExitsFourWithOneLineAndNoOutput) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--dt", "nan"}, "--dt"},
      {{"--dt", "-1"}, "--dt"},
      {{"--dt", "0"}, "--dt"},
      {{"--duration", "inf"}, "--duration"},
      {{"--duration", "-5"}, "--duration"},
      {{"--duration", "1e999"}, "--duration"},
      {{"--log-rate", "3"}, "--log-rate"},    // 1/(3 * 0.005) = 66.7 steps per row
      {{"--log-rate", "400"}, "--log-rate"},  // faster than the steps
      {{"--log-rate", "-10"}, "--log-rate"},
      {{"--duration", "5.05"}, "--duration"},  // not a whole number of 0.1 s rows
      {{"--duration", "1.0001"}, "--duration"},
  };
  for (const auto& [args, culprit] : cases) {
    std::vector<std::string> full = {"--robot", "RT", "--path", "circle"};
    full.insert(full.end(), args.begin(), args.end());
    const Process process = terrain(full);
    EXPECT_EQ(process.status, cli::kInvalidInput) << args.back() << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    EXPECT_EQ(std::count(process.err.begin(), process.err.end(), '\n'), 1) << process.err;
    expectNoOutputFiles();
  }
}

TEST_F(SphereSimTest, ImplausibleNumbersOfEverySubcommandAreInvalidInput) {
  // Finite but far outside any physical range: each was taken as a number and then hung
  // (rotor-step), crashed (norma: exit 1), overflowed into a NaN message (roller) or an answer
  // (freebot-ik "position error 0 m", freebot-wheels 7.6e301 rad/s).
  const std::string source = SPHERICAL_ROBOTS_SOURCE_DIR;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"norma", "--config", source, "--duration", "1e300"}, "samples"},
      {{"norma", "--config", source, "--log-rate", "1e300"}, "samples"},
      {{"rotor-step", "--k", "1e300", "--a", "0.3", "--b", "0.3", "--gamma", "0.9"},
       "inertia ratio k"},
      {{"rotor-plan", "--k", "2.5", "--steps", "1000000", "--target", "0,1,0"}, "steps"},
      {{"freebot-ik", "--radii", "0.034,0.034,0.034,0.034", "--target", "1e300,0,0",
        "--position-only"},
       "target x"},
      {{"freebot-fk", "--radii", "1e300,0.034,0.034,0.034", "--joints", "0.1,0.2;0.3,-0.1;0,0.4"},
       "radius"},
      {{"freebot-wheels", "--wheel-radius", "0.01", "--wheel-interval", "0.03", "--shell-radii",
        "0.03,0.034", "--trolley", "1e300,0.5"},
       "u_f"},
      {{"roller", "--r", "1e300", "--contacts", "215,60,325,60", "--alpha-deg", "10,-10",
        "--speed", "1", "--direction-deg", "90"},
       "sphere radius r"},
  };
  for (const auto& [args, culprit] : cases) {
    std::vector<std::string> full = args;
    full.insert(full.begin() + 1, {"--out", out_.string()});
    const Process process = run(full);
    EXPECT_EQ(process.status, cli::kInvalidInput) << args.front() << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    EXPECT_EQ(std::count(process.err.begin(), process.err.end(), '\n'), 1) << process.err;
    expectNoOutputFiles();
  }
}

TEST_F(SphereSimTest, RadiusBreakingSinglePointContactIsInvalidInput) {
  // Eq 59's valleys have curvature a w^2 = 0.8 1/m, so a 2 m sphere touches them at two points.
  const fs::path config = dir_ / "share";
  fs::create_directories(config / "config");
  fs::create_directories(config / "urdf");
  fs::copy_file(fs::path(SPHERICAL_ROBOTS_SOURCE_DIR) / "config" / "terrain.yaml",
                config / "config" / "terrain.yaml");
  std::ofstream(config / "urdf" / "terrain_robot.urdf")
      << "<robot name='big'><link name='shell'><collision><geometry><sphere radius='2.0'/>"
         "</geometry></collision></link></robot>\n";
  const Process process = run({"terrain", "--robot", "3R", "--path", "circle", "--config",
                               config.string(), "--out", out_.string()});
  EXPECT_EQ(process.status, cli::kInvalidInput) << process.err;
  EXPECT_NE(process.err.find("single-point contact"), std::string::npos) << process.err;
  EXPECT_FALSE(fs::exists(out_));
}

TEST_F(SphereSimTest, UnreadableConfigOrOutputIsInvalidInput) {
  const Process no_config = run({"terrain", "--robot", "3R", "--path", "circle", "--config",
                                 (dir_ / "nowhere").string(), "--out", out_.string()});
  EXPECT_EQ(no_config.status, cli::kInvalidInput);
  EXPECT_NE(no_config.err.find("nowhere"), std::string::npos) << no_config.err;
  EXPECT_FALSE(fs::exists(out_));

  const fs::path unwritable = dir_ / "missing_dir" / "run.csv";
  const Process no_dir =
      run({"terrain", "--robot", "3R", "--path", "circle", "--duration", "1", "--config",
           SPHERICAL_ROBOTS_SOURCE_DIR, "--out", unwritable.string()});
  EXPECT_EQ(no_dir.status, cli::kInvalidInput);
  EXPECT_NE(no_dir.err.find("missing_dir"), std::string::npos) << no_dir.err;
}

// --out names a device or a pipe (/dev/null, /dev/stdout, a named pipe): the rows go into it and
// it stays what it was. Writing a temporary file and renaming it over the path, as for a regular
// file, replaced root's /dev/null with a regular file (found in a benchmark run; this test uses a
// named pipe, which the old code replaced the same way, so that a regression cannot break the
// machine's /dev/null).
TEST_F(SphereSimTest, OutputIntoANamedPipeLeavesThePipeInPlace) {
  const fs::path pipe = dir_ / "rows.fifo";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0) << std::strerror(errno);
  // The read end, open before sphere_sim writes: a 1 s run's rows (about 3 kB) fit in the pipe's
  // buffer, so no reader has to run beside it, and a sphere_sim that never opens the pipe cannot
  // make this test wait.
  const int read_end = ::open(pipe.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(read_end, 0) << std::strerror(errno);
  const Process process = run({"terrain", "--robot", "3R", "--path", "circle", "--duration", "1",
                               "--config", SPHERICAL_ROBOTS_SOURCE_DIR, "--out", pipe.string()});
  std::string received;
  char chunk[4096];
  for (ssize_t n; (n = ::read(read_end, chunk, sizeof chunk)) > 0;) received.append(chunk, n);
  ::close(read_end);
  ASSERT_EQ(process.status, 0) << process.err;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(pipe))) << "the named pipe was replaced";
  EXPECT_EQ(received.rfind("t,x0,y0,", 0), 0u) << received.substr(0, 80);
  EXPECT_EQ(std::count(received.begin(), received.end(), '\n'), 12);  // header, t = 0 .. 1 s
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos)
        << "left behind: " << entry.path();
  }
}

// --out names a symbolic link: the file it names gets the rows, and the link stays a link.
TEST_F(SphereSimTest, OutputThroughASymbolicLinkWritesTheFileItNames) {
  fs::create_directory(dir_ / "data");
  const fs::path link = dir_ / "latest.csv";
  fs::create_symlink(dir_ / "data" / "run.csv", link);
  const Process process = run({"terrain", "--robot", "3R", "--path", "circle", "--duration", "1",
                               "--config", SPHERICAL_ROBOTS_SOURCE_DIR, "--out", link.string()});
  ASSERT_EQ(process.status, 0) << process.err;
  EXPECT_TRUE(fs::is_symlink(link)) << "the link was replaced by a file";
  ASSERT_TRUE(fs::is_regular_file(dir_ / "data" / "run.csv"));
  EXPECT_EQ(readCsv(dir_ / "data" / "run.csv").rows.size(), 11u);
}

// --- help --------------------------------------------------------------------------------------

TEST_F(SphereSimTest, HelpExplainsEveryOptionAndColumn) {
  const Process help = run({"terrain", "--help"});
  ASSERT_EQ(help.status, 0) << help.err;
  for (const char* option :
       {"--robot", "--path", "--model", "--law", "--duration", "--dt", "--log-rate", "--config",
        "--out"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
  for (const char* default_text :
       {"(default 200)", "(default 0.005)", "(default 10)", "(default paper)"}) {
    EXPECT_NE(help.out.find(default_text), std::string::npos) << default_text;
  }
  // --law's default and why it is the paper's (issue 13).
  EXPECT_NE(help.out.find("[--law {paper,smooth}]"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("reproduces the paper"), std::string::npos) << help.out;
  // Every column the tool writes is explained.
  ASSERT_EQ(terrain({"--robot", "3R", "--path", "circle", "--duration", "0"}).status, 0);
  for (const std::string& column : readCsv(out_).header) {
    EXPECT_TRUE(mentionsWord(help.out, column)) << column;
  }
  const Process top = run({"--help"});
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("terrain"), std::string::npos);
}

// --- the CSV -----------------------------------------------------------------------------------

/// Checks what every row must satisfy whatever the robot or path: the contact point and the
/// desired point lie on the surface, e_norm is their distance, and the centre is R along the
/// surface normal from the contact point.
void expectRowGeometry(const Csv& csv) {
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(i));
    const double x0 = csv.at(i, "x0"), y0 = csv.at(i, "y0"), z0 = csv.at(i, "z0");
    const double xd = csv.at(i, "xd"), yd = csv.at(i, "yd"), zd = csv.at(i, "zd");
    EXPECT_NEAR(z0, surfaceHeight(x0, y0), kTight);
    EXPECT_NEAR(zd, surfaceHeight(xd, yd), kTight);
    EXPECT_NEAR(csv.at(i, "e_norm"), std::hypot(xd - x0, yd - y0, zd - z0), kTight);
    // n = (-f_x, -f_y, 1) / |.| with f_x = -a w sin(w x) (eq 10).
    const double fx = -kAmplitude * kFrequency * std::sin(kFrequency * x0);
    const double fy = -kAmplitude * kFrequency * std::sin(kFrequency * y0);
    const double s = kRadius / std::sqrt(1.0 + fx * fx + fy * fy);
    EXPECT_NEAR(csv.at(i, "cx"), x0 - s * fx, kTight);
    EXPECT_NEAR(csv.at(i, "cy"), y0 - s * fy, kTight);
    EXPECT_NEAR(csv.at(i, "cz"), z0 + s, kTight);
    EXPECT_GT(csv.at(i, "zeta"), -M_PI - kTight);
    EXPECT_LE(csv.at(i, "zeta"), M_PI + kTight);
  }
}

/// Rows at 0, period, 2 period, ... through duration inclusive.
void expectRowTimes(const Csv& csv, double period, double duration) {
  const auto rows = static_cast<std::size_t>(std::lround(duration / period)) + 1;
  ASSERT_EQ(csv.rows.size(), rows);
  for (std::size_t i = 0; i < rows; ++i) {
    EXPECT_NEAR(csv.at(i, "t"), static_cast<double>(i) * period, 1e-9 * std::max(1.0, duration))
        << "row " << i;
  }
}

TEST_F(SphereSimTest, CircleRunMatchesClosedForms) {
  // --duration after the other options, in the --name=value form.
  const Process process = terrain({"--robot", "3R", "--path", "circle", "--duration=20"});
  ASSERT_EQ(process.status, 0) << process.err;
  const Csv csv = readCsv(out_);
  for (const std::string& column : kRequiredColumns) csv.column(column);
  expectRowTimes(csv, 0.1, 20.0);
  expectRowGeometry(csv);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double t = csv.at(i, "t");
    EXPECT_NEAR(csv.at(i, "xd"), kCircleRadius * std::cos(kCircleRate * t), kTight) << "t=" << t;
    EXPECT_NEAR(csv.at(i, "yd"), kCircleRadius * std::sin(kCircleRate * t), kTight) << "t=" << t;
    EXPECT_EQ(csv.at(i, "phi"), 0.0);  // only RS tilts
  }
  // The start: the origin, heading 0, target at (2, 0) straight ahead.
  EXPECT_EQ(csv.at(0, "x0"), 0.0);
  EXPECT_EQ(csv.at(0, "psi"), 0.0);
  EXPECT_EQ(csv.at(0, "zeta"), 0.0);
  // One summary line, naming the run, that found the 3R converged within 20 s.
  EXPECT_EQ(std::count(process.out.begin(), process.out.end(), '\n'), 1) << process.out;
  for (const char* word : {"3R", "circle", "paper"}) {
    EXPECT_NE(process.out.find(word), std::string::npos) << process.out;
  }
  EXPECT_EQ(process.out.find("never"), std::string::npos) << process.out;
  EXPECT_LT(csv.rows.back().at(csv.column("e_norm")), 0.1);
}

// --law reaches the controller: on the circle after 40 s the paper's 3R turn rate k_psi zeta flips
// sign from one logged step to the next (zeta crosses +-pi at convergence, docs/results.md); the
// smooth law's never does. An unknown law names the option and the choices.
TEST_F(SphereSimTest, LawSelectsTheTrackingLaw) {
  const auto turnRateSignChanges = [this](const std::string& law) {
    const Process process = terrain({"--robot", "3R", "--path", "circle", "--law", law,
                                     "--duration", "60", "--log-rate", "200"});
    EXPECT_EQ(process.status, 0) << process.err;
    EXPECT_NE(process.out.find("law " + law), std::string::npos) << process.out;
    const Csv csv = readCsv(out_);
    int changes = 0;
    for (std::size_t i = 1; i < csv.rows.size(); ++i) {
      if (csv.at(i, "t") < 40.0) continue;
      changes += csv.at(i - 1, "turn_rate") * csv.at(i, "turn_rate") < 0.0;
    }
    return changes;
  };
  EXPECT_EQ(turnRateSignChanges("smooth"), 0);
  EXPECT_GT(turnRateSignChanges("paper"), 400);  // of 4000 steps
  EXPECT_EQ(terrain({"--robot", "3R", "--path", "circle"}).status, 0);
  EXPECT_NE(terrain({"--robot", "3R", "--path", "circle"}).out.find("law paper"), std::string::npos);
  const Process bad = terrain({"--robot", "3R", "--path", "circle", "--law", "Smooth"});
  EXPECT_EQ(bad.status, cli::kUsageError);
  for (const char* word : {"--law", "Smooth", "paper", "smooth"}) {
    EXPECT_NE(bad.err.find(word), std::string::npos) << word << ": " << bad.err;
  }
}

// Issue 13 let the paper's law use faster arithmetic on one condition: where it chatters its
// trajectories may move by rounding, but its first |e_t| < 0.1 m must stay within 0.1 s and its
// mean |e_t| after 40 s within 1 mm of the table it was filed against. That table (the terrain
// table of docs/results.md at 7ff3615^, rows logged at 10 Hz, printed to 0.01 s and 0.1 mm) is
// the reference here, not today's output; the figures are taken from the CSV as
// scripts/terrain_results.py takes them.
TEST_F(SphereSimTest, PaperLawStaysWithinIssue13sAllowanceOfTheTableItWasFiledAgainst) {
  struct Filed {
    const char* robot;
    const char* path;
    const char* model;
    double first_below;  // [s]
    double mean_after;   // [m]
  };
  const Filed filed[] = {
      {"3R", "circle", "paper", 6.40, 0.0001},   {"3R", "circle", "rolling", 6.60, 0.0097},
      {"3R", "diamond", "paper", 5.10, 0.0007},  {"3R", "diamond", "rolling", 5.20, 0.0034},
      {"2R", "circle", "paper", 5.30, 0.0405},   {"2R", "circle", "rolling", 5.40, 0.0401},
      {"2R", "diamond", "paper", 4.30, 0.0365},  {"2R", "diamond", "rolling", 4.30, 0.0346},
      {"RT", "circle", "paper", 8.00, 0.0000},   {"RT", "circle", "rolling", 8.20, 0.0113},
      {"RT", "diamond", "paper", 7.50, 0.0050},  {"RT", "diamond", "rolling", 7.50, 0.0074},
      {"RS", "circle", "paper", 19.90, 0.0026},  {"RS", "circle", "rolling", 17.90, 0.0334},
      {"RS", "diamond", "paper", 15.00, 0.0686}, {"RS", "diamond", "rolling", 15.40, 0.1012}};
  constexpr double kPrinted = 0.5e-4;  // the table's rounding of the mean [m]
  for (const Filed& f : filed) {
    const std::string name = std::string(f.robot) + " " + f.path + " " + f.model;
    const Process process = terrain(
        {"--robot", f.robot, "--path", f.path, "--model", f.model, "--law", "paper"});
    ASSERT_EQ(process.status, 0) << name << ": " << process.err;
    const Csv csv = readCsv(out_);
    double first_below = std::nan("");
    double sum_after = 0.0;
    int count_after = 0;
    for (std::size_t i = 0; i < csv.rows.size(); ++i) {
      const double t = csv.at(i, "t");
      const double error = csv.at(i, "e_norm");
      if (std::isnan(first_below) && error < 0.1) first_below = t;
      if (t >= 40.0) {
        sum_after += error;
        ++count_after;
      }
    }
    ASSERT_GT(count_after, 0) << name;
    EXPECT_LE(std::abs(first_below - f.first_below), 0.1 + 1e-9) << name << ": " << first_below;
    EXPECT_LE(std::abs(sum_after / count_after - f.mean_after), 1e-3 + kPrinted)
        << name << ": " << sum_after / count_after;
  }
}

TEST_F(SphereSimTest, SampledLoopRunsAtTheStacksStepsAndStartsWhereTheContinuousRunStarts) {
  const Process sampled = terrain({"--robot", "RS", "--path", "diamond", "--law", "smooth",
                                   "--loop", "sampled", "--duration", "20", "--log-rate", "50"});
  ASSERT_EQ(sampled.status, 0) << sampled.err;
  const Csv rows = readCsv(out_);
  ASSERT_EQ(rows.rows.size(), 1001u);  // t = 0, 0.02, ..., 20: the stack's terrain_state times
  EXPECT_EQ(rows.at(1000, "t"), 20.0);
  EXPECT_LT(rows.at(1000, "e_norm"), 0.1);  // it tracks
  ASSERT_EQ(terrain({"--robot", "RS", "--path", "diamond", "--law", "smooth", "--duration", "20",
                     "--log-rate", "50"}).status, 0);
  const Csv continuous = readCsv(out_);
  // At t = 0 both are the initial state and the law's error on it; the sampled robot's realised
  // rates are its actuators', still at rest, where the continuous one realises the command.
  for (const std::string& column : rows.header) {
    if (column.size() > 5 && column.substr(column.size() - 5) == "_rate")
      EXPECT_EQ(rows.at(0, column), 0.0) << column;
    else
      EXPECT_EQ(rows.at(0, column), continuous.at(0, column)) << column;
  }
  // The stack's sampling (10 ms steps, 50 Hz control, actuators within 50 rad/s^2) is not the
  // continuous loop: the paths differ, though not by much.
  const double apart = std::hypot(rows.at(1000, "x0") - continuous.at(1000, "x0"),
                                  rows.at(1000, "y0") - continuous.at(1000, "y0"));
  EXPECT_GT(apart, 1e-6);
  EXPECT_LT(apart, 0.05);
  // A step that is no whole number of nanoseconds' multiple of the log period, or a bad name.
  EXPECT_EQ(terrain({"--robot", "3R", "--path", "circle", "--loop", "sampled", "--dt", "0.03",
                     "--duration", "20", "--log-rate", "50"}).status, cli::kInvalidInput);
  const Process bad = terrain({"--robot", "3R", "--path", "circle", "--loop", "lockstep"});
  EXPECT_EQ(bad.status, cli::kUsageError);
  EXPECT_NE(bad.err.find("--loop"), std::string::npos) << bad.err;
}

/// A height map of eq 59 sampled every 0.1 m over [-e, e]^2 as a CSV grid (first line the +y edge,
/// every digit kept) and its YAML, in dir; returns the YAML's path.
fs::path writeEq59Map(const fs::path& dir, double half_extent, const std::string& name) {
  const int n = static_cast<int>(std::lround(2 * half_extent / 0.1)) + 1;
  std::ofstream csv(dir / (name + ".csv"));
  csv.precision(17);
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      csv << (column ? "," : "") << surfaceHeight(-half_extent + 0.1 * column,
                                                  half_extent - 0.1 * row);
    }
    csv << "\n";
  }
  std::ofstream yaml(dir / (name + ".yaml"));
  yaml << "csv: " << name << ".csv\nresolution: 0.1\norigin: [" << -half_extent - 0.05 << ", "
       << -half_extent - 0.05 << "]\n";
  return dir / (name + ".yaml");
}

TEST_F(SphereSimTest, TerrainOptionRunsOnAHeightMapAsOnItsAnalyticSurface) {
  // test_height_map_tracking's bound, through the command line: every logged contact point of
  // the run on eq 59 sampled every 0.1 m is within 2e-5 m of the run on eq 59.
  const std::vector<std::string> args = {"--robot", "RS", "--path", "circle", "--law", "smooth",
                                         "--duration", "60"};
  ASSERT_EQ(terrain(args).status, 0);
  const Csv analytic = readCsv(out_);
  std::vector<std::string> on_map = args;
  on_map.insert(on_map.end(), {"--terrain", writeEq59Map(dir_, 3.5, "eq59").string()});
  const Process process = terrain(on_map);
  ASSERT_EQ(process.status, 0) << process.err;
  EXPECT_EQ(process.err, "");
  const Csv mapped = readCsv(out_);
  ASSERT_EQ(mapped.rows.size(), analytic.rows.size());
  for (std::size_t row = 0; row < mapped.rows.size(); ++row) {
    const double gap = std::hypot(std::hypot(mapped.at(row, "x0") - analytic.at(row, "x0"),
                                             mapped.at(row, "y0") - analytic.at(row, "y0")),
                                  mapped.at(row, "z0") - analytic.at(row, "z0"));
    ASSERT_LT(gap, 2e-5) << "t = " << mapped.at(row, "t");
  }
  fs::remove(out_);

  // A map the circle leaves: exit 4, the point and the map named, no output.
  on_map.back() = writeEq59Map(dir_, 1.5, "small").string();
  const Process off = terrain(on_map);
  EXPECT_EQ(off.status, cli::kInvalidInput);
  EXPECT_NE(off.err.find("off the height map"), std::string::npos) << off.err;
  EXPECT_NE(off.err.find("small.csv"), std::string::npos) << off.err;
  fs::remove(dir_ / "eq59.csv");
  fs::remove(dir_ / "eq59.yaml");
  fs::remove(dir_ / "small.csv");
  fs::remove(dir_ / "small.yaml");
  expectNoOutputFiles();
  const Process missing = terrain({"--robot", "3R", "--path", "circle", "--terrain", "nowhere.yaml"});
  EXPECT_EQ(missing.status, cli::kInvalidInput);
  EXPECT_NE(missing.err.find("nowhere.yaml"), std::string::npos) << missing.err;
}

class SphereSimRobotTest : public SphereSimTest,
                           public ::testing::WithParamInterface<const char*> {};

TEST_P(SphereSimRobotTest, DiamondRunRespectsTheRobotsConstraints) {
  const std::string robot = GetParam();
  const Process process = terrain({"--robot", robot, "--path", "diamond", "--duration", "5", "--dt",
                                   "0.01", "--log-rate", "4", "--model", "rolling"});
  ASSERT_EQ(process.status, 0) << process.err;
  const Csv csv = readCsv(out_);
  expectRowTimes(csv, 0.25, 5.0);
  expectRowGeometry(csv);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double t = csv.at(i, "t");
    // First edge, (d, 0) -> (0, d), at constant XY speed.
    const double along = kDiamondSpeed * t / std::sqrt(2.0);
    EXPECT_NEAR(csv.at(i, "xd"), kDiamondHalf - along, kTight) << "t=" << t;
    EXPECT_NEAR(csv.at(i, "yd"), along, kTight) << "t=" << t;
    // Unactuated rates are zero (docs/conventions.md, table of types).
    // (2R's psi is not 0 here: in the rolling model the heading is parallel-transported while
    // psi is measured from the tangent frame, which turns by itself over curved ground.)
    if (robot == "2R") {
      EXPECT_EQ(csv.at(i, "turn_rate"), 0.0);
    }
    if (robot == "RT") {
      EXPECT_EQ(csv.at(i, "lateral_rate"), 0.0);
    }
    if (robot == "RS") {
      EXPECT_LE(std::abs(csv.at(i, "phi")), kTiltLimit + kTight);
      EXPECT_NEAR(csv.at(i, "turn_rate"), -csv.at(i, "roll_rate") * std::sin(csv.at(i, "phi")),
                  kTight);  // eq 44
    } else {
      EXPECT_EQ(csv.at(i, "phi"), 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, SphereSimRobotTest, ::testing::Values("3R", "2R", "RT", "RS"));

TEST_F(SphereSimTest, ValuesMayStartWithADash) {
  // "-0" is a value, not an option: a zero-length run with its single row at t = 0.
  ASSERT_EQ(terrain({"--robot", "RS", "--path", "circle", "--duration", "-0"}).status, 0);
  EXPECT_EQ(readCsv(out_).rows.size(), 1u);
  // A relative output file whose name starts with '-'.
  const Process dashed = run({"terrain", "--robot", "2R", "--path", "circle", "--duration", "1",
                              "--config", SPHERICAL_ROBOTS_SOURCE_DIR, "--out", "-run.csv"},
                             dir_);
  ASSERT_EQ(dashed.status, 0) << dashed.err;
  EXPECT_EQ(readCsv(dir_ / "-run.csv").rows.size(), 11u);
}

TEST_F(SphereSimTest, FindsItsConfigWithoutTheConfigOption) {
  const Process process = run(
      {"terrain", "--robot", "RT", "--path", "circle", "--duration", "1", "--out", out_.string()});
  ASSERT_EQ(process.status, 0) << process.err;
  EXPECT_EQ(readCsv(out_).rows.size(), 11u);
}

// --- the shared option parser, in-process
// ---------------------------------------------------------

cli::Subcommand listCommand() {
  cli::Subcommand command;
  command.name = "demo";
  command.options = {{"target", "X,Y,Z", "a point", "", true, {}},
                     {"gain", "K", "a gain", "1.5", false, {}},
                     {"open-loop", "", "a flag", "", false, {}}};
  return command;
}

TEST(SphereSimCliTest, ListsAcceptNegativeNumbersAndCheckTheirLength) {
  const cli::Subcommand command = listCommand();
  const cli::ParsedOptions options = cli::parseOptions(command, {"--target", "-0.15,-0.25,7"});
  EXPECT_EQ(options.numberList("target", 3), (std::vector<double>{-0.15, -0.25, 7.0}));
  EXPECT_EQ(options.number("gain"), 1.5);  // the default
  EXPECT_FALSE(options.given("gain"));
  EXPECT_FALSE(options.flag("open-loop"));
  EXPECT_THROW(options.numberList("target", 2), cli::UsageError);

  EXPECT_THROW(cli::parseOptions(command, {"--target", "1,,2"}).numberList("target"),
               cli::UsageError);
  EXPECT_THROW(cli::parseOptions(command, {"--target", "1,nan,2"}).numberList("target"),
               cli::InvalidInput);
  EXPECT_EQ(cli::parseOptions(command, {"--target", "+2e-3"}).numberList("target"),
            std::vector<double>{2e-3});
}

TEST(SphereSimCliTest, FlagsTakeNoValue) {
  const cli::Subcommand command = listCommand();
  EXPECT_TRUE(cli::parseOptions(command, {"--open-loop", "--target", "0"}).flag("open-loop"));
  EXPECT_THROW(cli::parseOptions(command, {"--target", "0", "--open-loop=yes"}), cli::UsageError);
  EXPECT_THROW(cli::parseOptions(command, {"--open-loop"}), cli::UsageError);  // --target missing
}

TEST(SphereSimCliTest, NumbersAreFiniteOrInvalid) {
  const cli::Subcommand command = listCommand();
  const auto gain = [&](const std::string& text) {
    return cli::parseOptions(command, {"--target", "0", "--gain", text}).number("gain");
  };
  EXPECT_EQ(gain("-2.5"), -2.5);
  EXPECT_EQ(gain("1e-3"), 1e-3);
  for (const char* bad : {"nan", "-inf", "infinity", "1e400"}) {
    EXPECT_THROW(gain(bad), cli::InvalidInput) << bad;
  }
  for (const char* malformed : {"", "1.5x", " 1", "0x10", "+-1", "1,2"}) {
    EXPECT_THROW(gain(malformed), cli::UsageError) << malformed;
  }
}

TEST(SphereSimCliTest, FormatsNumbersAtFullPrecision) {
  for (const double value : {0.1, 1.0 / 3.0, -2.7182818284590451, 1e-300, 6.02214076e23}) {
    EXPECT_EQ(std::strtod(cli::formatNumber(value).c_str(), nullptr), value);
  }
  EXPECT_EQ(cli::formatNumber(0.1), "0.1");
  EXPECT_EQ(cli::formatNumber(-0.0), "0");
}

// --- JSON ------------------------------------------------------------------------------------

/// A JSON value read back strictly: anything that is not JSON makes parseJson throw.
struct Json {
  enum class Type { Null, Boolean, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0.0;
  std::string text;  // a string's value, or a number's literal as written
  std::vector<Json> items;
  std::vector<std::pair<std::string, Json>> members;  // in file order

  bool has(const std::string& key) const {
    return std::any_of(members.begin(), members.end(),
                       [&](const auto& m) { return m.first == key; });
  }
  const Json& operator[](const std::string& key) const {
    for (const auto& member : members) {
      if (member.first == key) return member.second;
    }
    throw std::runtime_error("no member " + key);
  }
};

class JsonParser {
 public:
  explicit JsonParser(std::string text) : text_(std::move(text)) {}

  Json parse() {
    Json result = value();
    skipSpace();
    if (at_ != text_.size()) fail("text after the value");
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(at_));
  }
  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool take(char c) {
    skipSpace();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'");
  }
  bool takeWord(const std::string& word) {
    if (text_.compare(at_, word.size(), word) != 0) return false;
    at_ += word.size();
    return true;
  }
  std::string string() {
    expect('"');
    std::string out;
    while (at_ < text_.size() && text_[at_] != '"') {
      if (static_cast<unsigned char>(text_[at_]) < 0x20) fail("control character in a string");
      if (text_[at_] == '\\') {
        if (++at_ >= text_.size()) fail("unfinished escape");
        const char c = text_[at_];
        if (c == 'u') {
          if (at_ + 4 >= text_.size()) fail("short \\u escape");
          out += static_cast<char>(std::stoi(text_.substr(at_ + 1, 4), nullptr, 16));
          at_ += 4;
        } else if (std::string("\"\\/").find(c) != std::string::npos) {
          out += c;
        } else {
          const std::map<char, char> escapes = {
              {'n', '\n'}, {'t', '\t'}, {'r', '\r'}, {'b', '\b'}, {'f', '\f'}};
          const auto escape = escapes.find(c);
          if (escape == escapes.end()) fail("bad escape");
          out += escape->second;
        }
        ++at_;
      } else {
        out += text_[at_++];
      }
    }
    expect('"');
    return out;
  }
  Json value() {
    skipSpace();
    if (at_ >= text_.size()) fail("missing value");
    Json result;
    const char c = text_[at_];
    if (c == '{') {
      result.type = Json::Type::Object;
      ++at_;
      if (take('}')) return result;
      do {
        skipSpace();
        std::string key = string();
        expect(':');
        result.members.emplace_back(std::move(key), value());
      } while (take(','));
      expect('}');
    } else if (c == '[') {
      result.type = Json::Type::Array;
      ++at_;
      if (take(']')) return result;
      do {
        result.items.push_back(value());
      } while (take(','));
      expect(']');
    } else if (c == '"') {
      result.type = Json::Type::String;
      result.text = string();
    } else if (takeWord("true") || takeWord("false")) {
      result.type = Json::Type::Boolean;
      result.boolean = c == 't';
    } else if (takeWord("null")) {
      result.type = Json::Type::Null;
    } else {
      // JSON's number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
      const std::size_t start = at_;
      const auto digits = [&] {
        const std::size_t first = at_;
        while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_]))) ++at_;
        if (at_ == first) fail("expected a digit");
      };
      if (text_[at_] == '-') ++at_;
      if (at_ < text_.size() && text_[at_] == '0') {
        ++at_;
      } else {
        digits();
      }
      if (at_ < text_.size() && text_[at_] == '.') {
        ++at_;
        digits();
      }
      if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
        ++at_;
        if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
        digits();
      }
      result.type = Json::Type::Number;
      result.text = text_.substr(start, at_ - start);
      result.number = std::strtod(result.text.c_str(), nullptr);
    }
    return result;
  }

  std::string text_;
  std::size_t at_ = 0;
};

Json parseJson(const std::string& text) { return JsonParser(text).parse(); }

/// value as printf's %.17g writes it: 17 significant digits, trailing zeros dropped.
std::string printf17(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

TEST(JsonWriterTest, WritesNestedValuesAtSeventeenDigits) {
  std::ostringstream out;
  cli::JsonWriter json(out);
  json.text("name", "a \"quoted\"\\path\n")
      .number("tenth", 0.1)
      .number("one", 1.0)
      .number("negative_zero", -0.0)
      .numbers("omega", {-1.0, 1.0 / 3.0, 6.02214076e23})
      .numbers("none", {})
      .boolean("ok", true)
      .beginObject("half")
      .number("u", 2.5)
      .end()
      .beginArray("solutions")
      .beginObject()
      .number("a", 1e-300)
      .end()
      .beginObject()
      .end()
      .end()
      .finish();
  EXPECT_EQ(out.str(),
            "{\n"
            "  \"name\": \"a \\\"quoted\\\"\\\\path\\u000a\",\n"
            "  \"tenth\": 0.10000000000000001,\n"
            "  \"one\": 1,\n"
            "  \"negative_zero\": 0,\n"
            "  \"omega\": [-1, 0.33333333333333331, 6.0221407599999999e+23],\n"
            "  \"none\": [],\n"
            "  \"ok\": true,\n"
            "  \"half\": {\n"
            "    \"u\": 2.5\n"
            "  },\n"
            "  \"solutions\": [\n"
            "    {\n"
            "      \"a\": 1e-300\n"
            "    },\n"
            "    {}\n"
            "  ]\n"
            "}\n");
  const Json read = parseJson(out.str());
  EXPECT_EQ(read["name"].text, "a \"quoted\"\\path\n");
  EXPECT_EQ(read["tenth"].number, 0.1);
  EXPECT_EQ(read["omega"].items.at(1).number, 1.0 / 3.0);
  EXPECT_EQ(read["solutions"].items.at(0)["a"].number, 1e-300);
  for (const double value : {0.1, 1.0 / 3.0, -2.7182818284590451, 1e-300, 6.02214076e23, 1e22}) {
    const std::string text = cli::JsonWriter::formatNumber17(value);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    EXPECT_EQ(text, printf17(value));
  }
}

TEST(JsonWriterTest, RejectsNonFiniteNumbersAndMisuse) {
  std::ostringstream out;
  cli::JsonWriter json(out);
  EXPECT_THROW(json.number("x", std::nan("")), std::runtime_error);
  EXPECT_THROW(json.numbers("v", {1.0, INFINITY}), std::runtime_error);
  EXPECT_EQ(out.str(), "{");                   // nothing of the rejected members was written
  EXPECT_THROW(json.end(), std::logic_error);  // only finish() closes the top level
  json.beginArray("list");
  EXPECT_THROW(json.number("keyed", 1.0), std::logic_error);  // arrays hold no keys
  EXPECT_THROW(json.finish(), std::logic_error);              // the array is still open
  json.end().finish();
  EXPECT_THROW(json.finish(), std::logic_error);
  EXPECT_THROW(json.number("late", 1.0), std::logic_error);
  EXPECT_NO_THROW(parseJson(out.str()));
}

// --- sphere_sim roller (Kimura et al. 2019) -----------------------------------------------------

/// Section 3 of the paper: r = 1 m, P1 at (215, 60) deg, P2 at (325, 60) deg (docs/errata.md, K5).
const std::vector<std::string> kPaperDrive = {"--r", "1", "--contacts", "215,60,325,60"};

class SphereSimRollerTest : public SphereSimTest {
 protected:
  void SetUp() override {
    SphereSimTest::SetUp();
    out_ = dir_ / "roller.json";
  }

  /// `sphere_sim roller ARGS --out out_`.
  Process roller(const std::vector<std::string>& args) const {
    std::vector<std::string> full = {"roller"};
    full.insert(full.end(), args.begin(), args.end());
    full.insert(full.end(), {"--out", out_.string()});
    return run(full);
  }

  /// The paper's drive with alpha2 = -alpha1, plus args; the JSON it wrote.
  Json paper(double alpha1_deg, const std::vector<std::string>& args) const {
    std::vector<std::string> full = kPaperDrive;
    full.insert(full.end(), {"--alpha-deg",
                             cli::formatNumber(alpha1_deg) + "," + cli::formatNumber(-alpha1_deg)});
    full.insert(full.end(), args.begin(), args.end());
    const Process process = roller(full);
    EXPECT_EQ(process.status, 0) << process.err;
    EXPECT_EQ(std::count(process.out.begin(), process.out.end(), '\n'), 1) << process.out;
    return parseJson(readFile(out_));
  }
};

const std::vector<std::string> kRollerKeys = {
    "omega", "speed", "direction_deg", "rho_deg", "v1", "v2", "S1", "S2"};

TEST_F(SphereSimRollerTest, InverseReproducesThePublishedSpeedsAtNinetyDegrees) {
  // Section 3 at phi = 90 deg, ||V|| = 1 m/s: |v_{i,k}| = 0.91, 0.93 and |S_{i,k}| = 0, 0.16 m/s
  // for alpha1 = 0, 10 deg. (The values for 20 and 30 deg do not reproduce: errata K6, and
  // test_friction_drive.)
  const std::vector<std::pair<double, std::pair<double, double>>> published = {
      {0.0, {0.91, 0.0}}, {10.0, {0.93, 0.16}}};
  for (const auto& [alpha, values] : published) {
    const Json json = paper(alpha, {"--speed", "1", "--direction-deg", "90"});
    for (const std::string& key : kRollerKeys) EXPECT_TRUE(json.has(key)) << key;
    EXPECT_EQ(json["mode"].text, "inverse");
    ASSERT_EQ(json["omega"].items.size(), 3u);
    EXPECT_NEAR(json["omega"].items[0].number, -1.0, 1e-12);
    EXPECT_NEAR(json["omega"].items[1].number, 0.0, 1e-12);
    EXPECT_NEAR(json["omega"].items[2].number, 0.0, 1e-12);
    EXPECT_NEAR(json["speed"].number, 1.0, 1e-12);
    EXPECT_NEAR(json["direction_deg"].number, 90.0, 1e-9);
    EXPECT_NEAR(json["rho_deg"].number, 0.0, 1e-9);
    for (const char* v : {"v1", "v2"}) {
      EXPECT_NEAR(json[v].number, values.first, 0.005) << v;  // signed: both positive
    }
    EXPECT_NEAR(json["S1"].number, values.second, 0.005);
    EXPECT_NEAR(json["S2"].number, -values.second, 0.005);  // S2 = -S1
    for (const auto& [key, value] : json.members) {
      if (value.type == Json::Type::Number) {
        EXPECT_EQ(value.text, printf17(value.number + 0.0)) << key;
      }
    }
  }
}

TEST_F(SphereSimRollerTest, ForwardOfTheInverseSpeedsGivesTheMotionBack) {
  const Json inverse = paper(20.0, {"--speed", "0.8", "--direction-deg", "-30"});
  EXPECT_NEAR(inverse["direction_deg"].number, 330.0, 1e-9);  // wrapped into [0, 360)
  const Json forward =
      paper(20.0, {"--roller-speeds", inverse["v1"].text + "," + inverse["v2"].text});
  EXPECT_EQ(forward["mode"].text, "forward");
  EXPECT_NEAR(forward["speed"].number, 0.8, 1e-12);
  EXPECT_NEAR(forward["direction_deg"].number, 330.0, 1e-9);
  EXPECT_NEAR(forward["rho_deg"].number, inverse["rho_deg"].number, 1e-9);
  for (const char* key : {"S1", "S2"}) {
    EXPECT_NEAR(forward[key].number, inverse[key].number, 1e-12) << key;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(forward["omega"].items.at(i).number, inverse["omega"].items.at(i).number, 1e-12);
  }
  // With slip: S1 = -S2 = (v1 sin 20 - v2 sin(-20)) / 2.
  const double lift =
      (inverse["v1"].number + inverse["v2"].number) * std::sin(20.0 * M_PI / 180.0) / 2;
  EXPECT_NEAR(forward["S1"].number, lift, 1e-12);
  EXPECT_GT(std::abs(lift), 0.01);
}

TEST_F(SphereSimRollerTest, DirectionsStayBelowThreeSixty) {
  // omega_x = 0, omega_y > 0 is phi = 0 (eq 14 as printed says 360, errata K3).
  const Json json = paper(0.0, {"--speed", "1", "--direction-deg", "-1e-14"});
  EXPECT_GE(json["direction_deg"].number, 0.0);
  EXPECT_LT(json["direction_deg"].number, 360.0);
  const Json zero = paper(0.0, {"--speed", "2", "--direction-deg", "720"});
  EXPECT_EQ(zero["direction_deg"].number, 0.0);
  const Json back = paper(0.0, {"--roller-speeds", zero["v1"].text + "," + zero["v2"].text});
  EXPECT_LT(back["direction_deg"].number, 360.0);
  EXPECT_NEAR(std::remainder(back["direction_deg"].number, 360.0), 0.0, 1e-9);
}

TEST_F(SphereSimRollerTest, UsageErrorsExitTwoWithNoOutput) {
  const std::vector<std::string> geometry = {"--r",           "1",           "--contacts",
                                             "215,60,325,60", "--alpha-deg", "10,-10"};
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--speed", "1", "--direction-deg", "90", "--roller-speeds", "1,1"}, "not both"},
      {{}, "--roller-speeds"},
      {{"--speed", "1"}, "--direction-deg"},
      {{"--direction-deg", "90"}, "--speed"},
      {{"--speed", "1", "--direction-deg", "9O"}, "9O"},
      {{"--roller-speeds", "1,2,3"}, "--roller-speeds"},
      {{"--roller-speeds", "1"}, "--roller-speeds"},
      {{"--roller-speeds", "1,2", "--gain", "3"}, "--gain"},
  };
  for (const auto& [args, culprit] : cases) {
    std::vector<std::string> full = geometry;
    full.insert(full.end(), args.begin(), args.end());
    const Process process = roller(full);
    EXPECT_EQ(process.status, cli::kUsageError) << culprit << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    EXPECT_NE(process.err.find("usage: sphere_sim roller"), std::string::npos) << process.err;
    expectNoOutputFiles();
  }
  for (const auto& [args, culprit] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--contacts", "215,60,325", "--alpha-deg", "0,0", "--r", "1"}, "--contacts"},
           {{"--contacts", "215,60,325,60", "--alpha-deg", "0", "--r", "1"}, "--alpha-deg"},
           {{"--contacts", "215,60,325,60", "--alpha-deg", "0,0"}, "--r"}}) {
    std::vector<std::string> full = args;
    full.insert(full.end(), {"--speed", "1", "--direction-deg", "0"});
    const Process process = roller(full);
    EXPECT_EQ(process.status, cli::kUsageError) << culprit << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    expectNoOutputFiles();
  }
}

TEST_F(SphereSimRollerTest, InvalidOrDegenerateInputExitsFourWithOneLineAndNoOutput) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--r", "0", "--contacts", "215,60,325,60", "--alpha-deg", "10,-10"}, "radius"},
      {{"--r", "-1", "--contacts", "215,60,325,60", "--alpha-deg", "10,-10"}, "radius"},
      {{"--r", "nan", "--contacts", "215,60,325,60", "--alpha-deg", "10,-10"}, "--r"},
      {{"--r", "1", "--contacts", "215,60,inf,60", "--alpha-deg", "10,-10"}, "--contacts"},
      {{"--r", "1", "--contacts", "215,60,215,60", "--alpha-deg", "10,-10"}, "parallel"},
      {{"--r", "1", "--contacts", "215,60,35,-60", "--alpha-deg", "10,-10"}, "antipodal"},
      {{"--r", "1", "--contacts", "215,60,325,60", "--alpha-deg", "90,-10"}, "cos(alpha1)"},
      {{"--r", "1", "--contacts", "215,60,325,60", "--alpha-deg", "10,-90"}, "cos(alpha2)"},
      {{"--r", "1", "--contacts", "0,0,0,90", "--alpha-deg", "0,0"}, "eq 18"},
  };
  for (const auto& [args, culprit] : cases) {
    std::vector<std::string> full = args;
    full.insert(full.end(), {"--speed", "1", "--direction-deg", "45"});
    const Process process = roller(full);
    EXPECT_EQ(process.status, cli::kInvalidInput) << culprit << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    EXPECT_EQ(std::count(process.err.begin(), process.err.end(), '\n'), 1) << process.err;
    expectNoOutputFiles();
  }
  const std::vector<std::pair<std::vector<std::string>, std::string>> mode_cases = {
      {{"--speed", "-1", "--direction-deg", "90"}, "speed"},
      {{"--speed", "nan", "--direction-deg", "90"}, "--speed"},
      {{"--speed", "1", "--direction-deg", "-inf"}, "--direction-deg"},
      {{"--roller-speeds", "0,0"}, "no horizontal component"},
      {{"--roller-speeds", "1,nan"}, "--roller-speeds"},
  };
  for (const auto& [args, culprit] : mode_cases) {
    std::vector<std::string> full = kPaperDrive;
    full.insert(full.end(), {"--alpha-deg", "10,-10"});
    full.insert(full.end(), args.begin(), args.end());
    const Process process = roller(full);
    EXPECT_EQ(process.status, cli::kInvalidInput) << culprit << ": " << process.err;
    EXPECT_NE(process.err.find(culprit), std::string::npos) << process.err;
    EXPECT_EQ(std::count(process.err.begin(), process.err.end(), '\n'), 1) << process.err;
    expectNoOutputFiles();
  }
}

TEST_F(SphereSimRollerTest, HelpExplainsEveryOptionAndMember) {
  const Process help = run({"roller", "--help"});
  ASSERT_EQ(help.status, 0) << help.err;
  for (const char* option : {"--r", "--contacts", "--alpha-deg", "--speed", "--direction-deg",
                             "--roller-speeds", "--out"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
  const Json json = paper(10.0, {"--roller-speeds", "1,0.5"});
  for (const auto& member : json.members) {
    EXPECT_TRUE(mentionsWord(help.out, member.first)) << member.first;
  }
  for (const char* topic : {"Exit status", "inverse", "forward", "eq 11", "eq 22", "eq 28"}) {
    EXPECT_NE(help.out.find(topic), std::string::npos) << topic;
  }
  EXPECT_NE(run({"--help"}).out.find("roller"), std::string::npos);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
