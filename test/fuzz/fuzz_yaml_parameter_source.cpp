// A YAML parameter file (config::YamlParameterSource) and every reader the nodes and sphere_sim
// run over one: terrain (and the controllers and paths it makes), roller, Norma, rotor, FreeBOT,
// actuator models, the hardware interface, odometry, the plant loop. Input: the file's text.
// A reader's error names the file; a height map's surface is left to fuzz_load_height_map.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "spherical_robots/config/actuator_models.hpp"
#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/config/hardware_interface_config.hpp"
#include "spherical_robots/config/norma_config.hpp"
#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/config/plant_loop_parameters.hpp"
#include "spherical_robots/config/roller_config.hpp"
#include "spherical_robots/config/rotor_config.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"

namespace {

using namespace spherical_robots;

/// Every key of the tree under prefix, read as each kind of value.
void readEverything(const config::ParameterSource& source, const std::string& prefix, int depth) {
  if (depth > 8) return;
  std::vector<std::string> keys;
  try {
    keys = source.keys(prefix).value_or(std::vector<std::string>{});
  } catch (const std::invalid_argument&) {
    return;
  }
  for (const std::string& key : keys) {
    const std::string path = prefix + key;
    for (const auto& read : std::vector<std::function<void()>>{
             [&] { source.number(path); }, [&] { source.text(path); },
             [&] { source.numbers(path); }, [&] { source.texts(path); }}) {
      try {
        read();
      } catch (const std::invalid_argument& error) {
        fuzz::requireNamesFile(error, source.origin());
      }
    }
    readEverything(source, path + "/", depth + 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::inputFile(data, size, "input.yaml");
  std::optional<config::YamlParameterSource> source;
  try {
    source.emplace(path, [](const std::string&) {});
  } catch (const std::invalid_argument& error) {
    fuzz::requireNamesFile(error, path);
    return 0;
  }
  readEverything(*source, "", 0);
  // A reader of the file: its error must name the file.
  const auto reading = [&](const std::function<void()>& read) {
    try {
      read();
    } catch (const std::invalid_argument& error) {
      fuzz::requireNamesFile(error, path);
    }
  };
  // What is made from values already read: its error names the value, not the file.
  const auto making = [](const std::function<void()>& make) {
    try {
      make();
    } catch (const std::invalid_argument&) {
    }
  };
  reading([&] {
    const config::TerrainConfig terrain = config::loadTerrainConfig(*source);
    if (terrain.surface.type != "height_map") making([&] { config::makeSurface(terrain.surface); });
    for (const char* name : {"circle", "diamond"}) making([&] { config::makePath(name, terrain); });
    for (const auto& type_name : terrain::kRobotTypeNames) {
      for (const terrain::PursuitLaw law : {terrain::PursuitLaw::Paper, terrain::PursuitLaw::Smooth}) {
        making([&] { config::makePursuitController(law, type_name.first, terrain, 0.2); });
      }
    }
  });
  reading([&] {
    const config::RollerConfig roller = config::loadRollerConfig(*source);
    making([&] { config::makeRollerActuation(roller, 0.2); });
  });
  for (const std::string& prefix : {std::string(), config::kNormaPlantKeys, config::kNormaControllerKeys}) {
    reading([&] { config::normaModelParameters(*source, prefix); });
    reading([&] { config::normaControlParameters(*source, prefix); });
  }
  reading([&] { config::rotorExecutiveParameters(*source, *source, config::kRotorPlannerKeys); });
  reading([&] { config::rotorManoeuvre(*source, "manoeuvre/"); });
  reading([&] { config::freebotChain(*source); });
  reading([&] { config::freebotGoalExecutive(*source); });
  reading([&] { config::loadActuatorModels(*source, {"rotor_1", "rotor_2"}); });
  reading([&] {
    config::makeSimulatedActuators(config::loadHardwareInterfaceSimParameters(*source));
  });
  reading([&] { config::loadOdometryParameters(*source); });
  reading([&] { config::loadPlantLoopParameters(*source, config::PlantLoopParameters()); });
  return 0;
}
