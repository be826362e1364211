// A user's path file (`sphere_sim terrain --path-file`, sphere_sim::readPathFile): read as an
// untimed path at 0.5 m/s and as a timed one. Input: the CSV text. Its errors name the file.
#include <optional>
#include <stdexcept>
#include <string>

#include "fuzz_input.hpp"
#include "path_file.hpp"
#include "sphere_sim_cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  const std::string path = fuzz::inputFile(data, size, "input.csv");
  for (const std::optional<double> speed : {std::optional<double>(0.5), std::optional<double>()}) {
    try {
      sphere_sim::readPathFile(path, speed);
    } catch (const sphere_sim::UsageError& error) {
      fuzz::requireNamesFile(error, path);
    } catch (const sphere_sim::InvalidInput& error) {
      fuzz::requireNamesFile(error, path);
    }
  }
  return 0;
}
