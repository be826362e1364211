#pragma once
// `sphere_sim terrain`: a closed-loop batch run of a spherical robot tracking a path over the
// terrain of Moazami et al. 2019, section 6, written as CSV.

#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "sphere_sim_cli.hpp"
#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/sampled_terrain_loop.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"

namespace spherical_robots::sphere_sim {

/// How the loop is run: continuous (the law at every RK4 stage) or sampled as the terrain stack
/// samples it (terrain::SampledTerrainLoop).
enum class TerrainLoop { Continuous, Sampled };

/// A terrain run as the command line describes it.
struct TerrainRunSettings {
  terrain::RobotType robot = terrain::RobotType::ThreeAxisRolling;
  std::string path = "circle";  ///< "circle" | "diamond"; unused with path_file
  std::string path_file;        ///< a CSV path (path_file.hpp) instead of path
  std::optional<double> speed;  ///< [m/s] along an x,y path_file
  terrain::ContactModel model = terrain::ContactModel::Paper;
  /// The paper's law by default: the subcommand reproduces the paper.
  terrain::PursuitLaw law = terrain::PursuitLaw::Paper;
  double duration = 200.0;  ///< [s], >= 0, a whole number of log periods
  TerrainLoop loop = TerrainLoop::Continuous;
  /// sampled: the stack replayed, "terrain" (launch/terrain_stack.launch) or "roller"
  /// (launch/roller_stack.launch: config/roller.yaml over config/terrain.yaml, the friction drive)
  std::string stack = "terrain";
  double dt = 0.005;        ///< RK4 step [s] > 0 (continuous); the plant's step (sampled)
  double log_rate = 10.0;   ///< CSV rows per second [Hz]; 1/log_rate a whole number of steps
  std::string config_dir;   ///< holds config/terrain.yaml and urdf/terrain_robot.urdf
  std::string terrain;      ///< a height map's YAML in place of terrain.yaml's surface; empty: none
  std::string actuator_models;  ///< sampled: a YAML file of actuator models; empty: ideal
};

/// A checked, ready-to-run scenario: the surface, path, kinematics and controller (of the
/// settings' law) that
/// config/terrain.yaml and urdf/terrain_robot.urdf describe for the settings' robot.
class TerrainRun {
 public:
  /// @throw InvalidInput naming the option whose value is out of range or misaligned with --dt,
  /// or the file that cannot be read (a path file: its bad line); std::invalid_argument from the core on a bad scenario
  /// (e.g. a radius that breaks single-point contact).
  explicit TerrainRun(const TerrainRunSettings& settings);
  TerrainRun(const TerrainRun&) = delete;
  TerrainRun& operator=(const TerrainRun&) = delete;

  /// Simulates from TerrainState{} (origin, psi = phi = 0) and writes the CSV to csv unless it
  /// is null. Can be called repeatedly; every call starts afresh.
  /// @return the tracking figures (|e_t| < 0.1 m, settling at 40 s) over the logged rows.
  /// @throw std::runtime_error if the state stops being finite.
  terrain::TrackingSummary simulate(std::ostream* csv) const;

  /// "robot 3R, path circle, model paper, law paper: |e_t| < 0.1 m at t = ... s; for t >= 40 s
  /// mean ..."
  std::string describe(const terrain::TrackingSummary& summary) const;

 private:
  /// One CSV row and the summary's sample.
  struct Row {
    double t;
    const terrain::TerrainState& state;
    const terrain::ContactGeometry& geometry;
    const terrain::DesiredPoint& desired;
    const terrain::TrackingError& error;
    const terrain::DriveRates& rates;
  };
  /// Runs `step` between rows and `row` for each, from t = 0 through the duration.
  template <typename Step, typename RowAt>
  terrain::TrackingSummary run(std::ostream* csv, Step step, RowAt row) const;

  TerrainRunSettings settings_;
  long steps_per_row_ = 0;
  long rows_ = 0;  // after the one at t = 0
  std::unique_ptr<terrain::Surface> surface_;
  std::unique_ptr<terrain::ReferencePath> path_;
  std::unique_ptr<terrain::TerrainKinematics> kinematics_;
  std::unique_ptr<terrain::PursuitController> controller_;
  terrain::StackSampling sampling_;
  std::unique_ptr<terrain::ActuatorDrive> drive_;  ///< null: the terrain stack's DirectDrive
};

/// The subcommand's option table and run function, for runSphereSim.
Subcommand terrainCommand();

}  // namespace spherical_robots::sphere_sim
