// A height map's raster file: config::readPgm. Input: the file's bytes. Its error names the file.
#include "fuzz_input.hpp"
#include "spherical_robots/config/height_map_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  fuzz::readInputFile(data, size, "input.pgm", config::readPgm);
  return 0;
}
