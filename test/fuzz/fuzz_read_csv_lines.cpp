// The CSV lines every CSV reader splits its file into (config::readCsvLines), and each cell as a
// number (config::csvNumber). Input: the text.
#include <sstream>
#include <string>

#include "fuzz_input.hpp"
#include "spherical_robots/config/csv_lines.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  for (const config::CsvLine& line : config::readCsvLines(in)) {
    for (const std::string& cell : line.cells) config::csvNumber(cell);
  }
  return 0;
}
