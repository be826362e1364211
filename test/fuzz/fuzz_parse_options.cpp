// sphere_sim's command line up to the point where a subcommand would start its run: the
// subcommand's option table (sphere_sim::parseOptions), then every given option's value read as
// each kind the subcommands read (number, integer, list, groups), and its --help. Input: one
// argument a line, the first the subcommand's name (`terrain`, `rotor-plan`, ...).
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "sphere_sim_cli.hpp"
#include "sphere_sim_commands.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots::sphere_sim;
  static const std::vector<Subcommand> commands = sphereSimCommands();
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::string> args;
  for (std::string line; std::getline(lines, line);) args.push_back(line);
  if (args.empty()) return 0;
  for (const Subcommand& command : commands) {
    if (command.name != args[0]) continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    std::ostringstream help;
    printHelp(command, help);
    try {
      const ParsedOptions options = parseOptions(command, rest);
      for (const OptionSpec& spec : command.options) {
        if (!options.given(spec.name) || spec.value_name.empty()) continue;
        options.text(spec.name);
        for (const auto& read : {+[](const ParsedOptions& o, const std::string& n) { o.number(n); },
                                 +[](const ParsedOptions& o, const std::string& n) { o.integer(n); },
                                 +[](const ParsedOptions& o, const std::string& n) { o.numberList(n); },
                                 +[](const ParsedOptions& o, const std::string& n) { o.numberGroups(n); }}) {
          try {
            read(options, spec.name);
          } catch (const UsageError&) {
          } catch (const InvalidInput&) {
          }
        }
      }
    } catch (const UsageError&) {
    }
  }
  return 0;
}
