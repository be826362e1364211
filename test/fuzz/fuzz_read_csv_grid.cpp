// A height map's raster file: config::readCsvGrid. Input: the file's bytes. Its error names the file.
#include <stdexcept>
#include <string>

#include "fuzz_input.hpp"
#include "spherical_robots/config/height_map_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  const std::string path = fuzz::inputFile(data, size, "input.csv");
  try {
    config::readCsvGrid(path);
  } catch (const std::invalid_argument& error) {
    fuzz::requireNamesFile(error, path);
  }
  return 0;
}
