#include "sphere_sim_cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>

#include "spherical_robots/config/robot_description.hpp"

namespace spherical_robots::sphere_sim {
namespace {

constexpr std::size_t kOutputBufferBytes = 1 << 20;

/// Whole of text as a double, as the command line allows it (a leading '+' too). Parsing and
/// judging are separate so that "nan" is invalid input (exit 4), not a usage error (exit 2).
double parseNumber(const std::string& option, const std::string& text) {
  const char* first = text.data();
  const char* last = first + text.size();
  // from_chars takes no '+', which a command line may carry; "+-1" stays malformed.
  if (last - first > 1 && first[0] == '+' && first[1] != '-') ++first;
  double value = 0.0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (first == last || end != last) {
    throw UsageError("--" + option + ": '" + text + "' is not a number");
  }
  if (error == std::errc::result_out_of_range) {
    throw InvalidInput("--" + option + ": " + text + " is out of the range of a double");
  }
  if (!std::isfinite(value)) {
    throw InvalidInput("--" + option + ": " + text + " is not a finite number");
  }
  return value;
}

/// "--name": an option, never a value (a value may start with one '-', as numbers do).
bool looksLikeOption(const std::string& token) {
  return token.size() > 2 && token.compare(0, 2, "--") == 0;
}

/// The longest shortest-round-trip double, "-1.2345678901234567e-308", is 24 characters.
constexpr std::size_t kMaxNumberLength = 24;

/// Writes formatNumber(value) at first, which has room for kMaxNumberLength characters; returns
/// the end of what it wrote.
char* writeNumber(char* first, double value) {
  // + 0.0 turns -0 into 0: the sign of a zero carries no meaning in the output.
  return std::to_chars(first, first + kMaxNumberLength, value + 0.0).ptr;
}

std::string valueSyntax(const OptionSpec& spec) {
  if (spec.choices.empty()) return spec.value_name;
  std::string syntax = "{";
  for (const std::string& choice : spec.choices) syntax += (syntax.size() > 1 ? "," : "") + choice;
  return syntax + "}";
}

std::string usageLine(const Subcommand& command) {
  std::string line = "usage: sphere_sim " + command.name;
  for (const OptionSpec& spec : command.options) {
    std::string item = "--" + spec.name;
    if (!spec.value_name.empty()) item += " " + valueSyntax(spec);
    line += spec.required ? " " + item : " [" + item + "]";
  }
  return line;
}

void printIndented(std::ostream& out, const std::string& text, const std::string& indent) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) out << indent << line << '\n';
}

/// Error messages are one line, whatever the core put into them.
std::string oneLine(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

void printTopLevelHelp(const std::vector<Subcommand>& commands, std::ostream& out) {
  out << R"(usage: sphere_sim SUBCOMMAND [OPTIONS] --out FILE
Batch runs of the spherical_robots models, over the same core, URDF and config/ files as the
ROS nodes.

subcommands:
)";
  for (const Subcommand& command : commands) {
    out << "  " << command.name << "  " << command.summary << '\n';
  }
  out << R"(
Run 'sphere_sim SUBCOMMAND --help' for its options and output. An option's value is the next
argument even if it begins with '-' (--target -0.15,-0.25,7); --name=VALUE works too. Lists
are comma-separated. nan and inf parse but are rejected as invalid input.
--out FILE appears only when the run succeeds (it is written beside and renamed); a symbolic
link's target is written, and a device or pipe (/dev/null, /dev/stdout) is written directly.
Exit status: 0 success; 2 usage error (unknown option, malformed value, missing option);
3 well-posed problem without a solution (output written); 4 invalid or degenerate input
(one-line error on stderr, no output file).
)";
}

}  // namespace

ParsedOptions::ParsedOptions(std::string command, std::map<std::string, std::string> values,
                             std::map<std::string, std::string> defaults)
    : command_(std::move(command)), values_(std::move(values)), defaults_(std::move(defaults)) {}

bool ParsedOptions::given(const std::string& name) const { return values_.count(name) > 0; }

const std::string& ParsedOptions::text(const std::string& name) const {
  if (const auto value = values_.find(name); value != values_.end()) return value->second;
  if (const auto fallback = defaults_.find(name); fallback != defaults_.end()) {
    return fallback->second;
  }
  throw std::logic_error("sphere_sim " + command_ + ": option --" + name +
                         " is neither given nor has a default");
}

double ParsedOptions::number(const std::string& name) const {
  return parseNumber(name, text(name));
}

int ParsedOptions::integer(const std::string& name) const {
  const double value = number(name);
  if (value != std::floor(value) || std::abs(value) > std::numeric_limits<int>::max()) {
    throw UsageError("--" + name + ": '" + text(name) + "' is not an integer");
  }
  return static_cast<int>(value);
}

std::vector<double> ParsedOptions::numberList(const std::string& name, std::size_t count) const {
  const std::string& list = text(name);
  std::vector<double> numbers;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = list.find(',', begin);
    numbers.push_back(parseNumber(name, list.substr(begin, comma - begin)));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  if (count != 0 && numbers.size() != count) {
    throw UsageError("--" + name + ": '" + list + "' has " + std::to_string(numbers.size()) +
                     " numbers, expected " + std::to_string(count));
  }
  return numbers;
}

std::vector<std::vector<double>> ParsedOptions::numberGroups(const std::string& name,
                                                             std::size_t count) const {
  const std::string& list = text(name);
  std::vector<std::vector<double>> groups;
  std::size_t begin = 0;
  while (true) {
    const std::size_t semicolon = list.find(';', begin);
    const std::string group = list.substr(begin, semicolon - begin);
    std::vector<double> numbers;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = group.find(',', start);
      numbers.push_back(parseNumber(name, group.substr(start, comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (count != 0 && numbers.size() != count) {
      throw UsageError("--" + name + ": group " + std::to_string(groups.size() + 1) + " '" + group +
                       "' has " + std::to_string(numbers.size()) + " numbers, expected " +
                       std::to_string(count));
    }
    groups.push_back(std::move(numbers));
    if (semicolon == std::string::npos) break;
    begin = semicolon + 1;
  }
  return groups;
}

ParsedOptions parseOptions(const Subcommand& command, const std::vector<std::string>& args) {
  std::map<std::string, std::string> values;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& token = args[i];
    if (!looksLikeOption(token)) {
      throw UsageError("unexpected argument '" + token + "'");
    }
    std::string name = token.substr(2);
    std::optional<std::string> attached;
    if (const std::size_t equals = name.find('='); equals != std::string::npos) {
      attached = name.substr(equals + 1);
      name.resize(equals);
    }
    const auto spec = std::find_if(command.options.begin(), command.options.end(),
                                   [&](const OptionSpec& option) { return option.name == name; });
    if (spec == command.options.end()) throw UsageError("unknown option --" + name);
    if (values.count(name) > 0) throw UsageError("option --" + name + " given twice");

    std::string value;
    if (spec->value_name.empty()) {
      if (attached) throw UsageError("option --" + name + " takes no value");
    } else if (attached) {
      value = *attached;
    } else if (i + 1 < args.size() && !looksLikeOption(args[i + 1])) {
      // The next token is the value even if it starts with '-': "--target -0.15,-0.25,7".
      value = args[++i];
    } else {
      std::string message = "option --" + name + " needs a value " + valueSyntax(*spec);
      if (i + 1 < args.size()) message += " (a value starting with -- needs --" + name + "=VALUE)";
      throw UsageError(message);
    }
    if (!spec->choices.empty() &&
        std::find(spec->choices.begin(), spec->choices.end(), value) == spec->choices.end()) {
      throw UsageError("--" + name + ": '" + value + "' is not one of " + valueSyntax(*spec));
    }
    values.emplace(name, std::move(value));
  }

  std::map<std::string, std::string> defaults;
  for (const OptionSpec& spec : command.options) {
    if (spec.required && values.count(spec.name) == 0) {
      throw UsageError("missing required option --" + spec.name);
    }
    if (!spec.default_value.empty()) defaults.emplace(spec.name, spec.default_value);
  }
  return ParsedOptions(command.name, std::move(values), std::move(defaults));
}

void printHelp(const Subcommand& command, std::ostream& out) {
  out << usageLine(command) << "\n\n" << command.summary << "\n\noptions:\n";
  for (const OptionSpec& spec : command.options) {
    out << "  --" << spec.name;
    if (!spec.value_name.empty()) out << ' ' << valueSyntax(spec);
    if (spec.required) out << "  (required)";
    if (!spec.default_value.empty()) out << "  (default " << spec.default_value << ')';
    out << '\n';
    printIndented(out, spec.help, "      ");
  }
  out << "  --help\n      Show this help and exit.\n\n";
  out << command.description;
}

int runSphereSim(const std::vector<Subcommand>& commands, const std::vector<std::string>& args,
                 std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    printTopLevelHelp(commands, err);
    return kUsageError;
  }
  if (args[0] == "--help" || args[0] == "-h") {
    printTopLevelHelp(commands, out);
    return kSuccess;
  }
  const auto command = std::find_if(commands.begin(), commands.end(),
                                    [&](const Subcommand& c) { return c.name == args[0]; });
  if (command == commands.end()) {
    err << "sphere_sim: unknown subcommand '" << args[0] << "'\n";
    printTopLevelHelp(commands, err);
    return kUsageError;
  }

  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (std::any_of(rest.begin(), rest.end(),
                  [](const std::string& a) { return a == "--help" || a == "-h"; })) {
    printHelp(*command, out);
    return kSuccess;
  }
  const std::string prefix = "sphere_sim " + command->name + ": ";
  try {
    return command->run(parseOptions(*command, rest), out);
  } catch (const UsageError& error) {
    err << prefix << oneLine(error.what()) << '\n'
        << usageLine(*command) << "\nRun 'sphere_sim " << command->name
        << " --help' for details.\n";
    return kUsageError;
  } catch (const std::invalid_argument& error) {  // the core's verdict on bad values
    err << prefix << "invalid input: " << oneLine(error.what()) << '\n';
    return kInvalidInput;
  } catch (const std::runtime_error& error) {  // InvalidInput, a diverging run, unreadable files
    err << prefix << "error: " << oneLine(error.what()) << '\n';
    return kInvalidInput;
  } catch (const std::exception& error) {  // a bug, not the user's input
    err << prefix << "internal error: " << oneLine(error.what()) << '\n';
    return kInternalError;
  }
}

OptionSpec optionalOption(std::string name, std::string value_name, std::string help,
                          std::string default_value) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.value_name = std::move(value_name);
  spec.help = std::move(help);
  spec.default_value = std::move(default_value);
  return spec;
}

OptionSpec requiredOption(std::string name, std::string value_name, std::string help) {
  OptionSpec spec = optionalOption(std::move(name), std::move(value_name), std::move(help));
  spec.required = true;
  return spec;
}

OptionSpec flagOption(std::string name, std::string help) {
  return optionalOption(std::move(name), "", std::move(help));
}

OptionSpec outOption(const std::string& what) {
  return requiredOption(
      "out", "FILE", what + "\nWritten only if the run succeeds (exit 0 or 3); never partially.");
}

OptionSpec configOption() {
  return optionalOption(
      "config", "DIR",
      "Directory holding config/ and urdf/ (a source tree or an installed share directory).\n"
      "Default: the installed spherical_robots share directory; no ROS environment is needed.");
}

namespace {

/// Step counts beyond this are a typo (--dt 5e-9), not a batch run; it also keeps them exact
/// in a double and a long.
constexpr double kMaxSteps = 1e9;
/// How close a ratio of times must be to a whole number: row times are exact multiples of dt.
constexpr double kWholeTolerance = 1e-9;

}  // namespace

long wholeSteps(double span, double step, const std::string& what) {
  const double steps = span / step;
  if (!(steps <= kMaxSteps)) {
    throw InvalidInput(what + " is " + formatNumber(steps) + " steps, more than the " +
                       formatNumber(kMaxSteps) + " a run allows");
  }
  const double whole = std::round(steps);
  if (std::abs(steps - whole) > kWholeTolerance * steps) {
    throw InvalidInput(what + " is " + formatNumber(steps) + " steps, not a whole number");
  }
  return static_cast<long>(whole);
}

double radiusFromUrdf(const std::string& path, const std::string& link) {
  const std::string xml = config::readTextFile(path);  // its error names the path
  try {
    return config::sphereRadiusFromUrdf(xml, link);
  } catch (const std::invalid_argument& error) {
    throw InvalidInput(path + ": " + error.what());
  }
}

std::string configDirectory(const ParsedOptions& options) {
  return options.given("config") ? options.text("config") : config::packageShareDirectory();
}

namespace {

// Where the temporary file is renamed to: path, or the file a symbolic link at path names (a
// rename onto the link would replace the link); empty if path exists and is not a regular file.
std::string renameTarget(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status target = std::filesystem::status(path, error);
  if (std::filesystem::exists(target) && !std::filesystem::is_regular_file(target)) return {};
  if (!std::filesystem::is_symlink(std::filesystem::symlink_status(path, error))) return path;
  // The link's target need not exist yet, where weakly_canonical(path) would not follow the link.
  std::filesystem::path target_path = std::filesystem::read_symlink(path, error);
  if (error) return path;
  if (target_path.is_relative()) {
    target_path = std::filesystem::path(path).parent_path() / target_path;
  }
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(target_path, error);
  return error ? path : resolved.string();
}

}  // namespace

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)), rename_path_(renameTarget(path_)),
      buffer_(new char[kOutputBufferBytes]) {
  if (!rename_path_.empty()) {
    temporary_path_ = rename_path_ + ".partial-" + std::to_string(::getpid());
  }
  const bool direct = rename_path_.empty();
  // The buffer must be installed before open() for libstdc++ to use it.
  stream_.rdbuf()->pubsetbuf(buffer_.get(), kOutputBufferBytes);
  stream_.open(direct ? path_ : temporary_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    throw InvalidInput("--out " + path_ + ": cannot " +
                       (direct ? std::string("open it") : "create " + temporary_path_) + ": " +
                       std::strerror(errno));
  }
}

OutputFile::~OutputFile() {
  if (committed_) return;
  stream_.close();
  if (!temporary_path_.empty()) std::remove(temporary_path_.c_str());
}

void OutputFile::commit() {
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || !stream_) throw std::runtime_error("--out " + path_ + ": writing failed");
  if (!rename_path_.empty() && std::rename(temporary_path_.c_str(), rename_path_.c_str()) != 0) {
    throw std::runtime_error("--out " + path_ + ": cannot rename " + temporary_path_ +
                             " to it: " + std::strerror(errno));
  }
  committed_ = true;
}

std::string formatNumber(double value) {
  char digits[kMaxNumberLength];
  return std::string(digits, writeNumber(digits, value));
}

CsvWriter::CsvWriter(std::ostream& out, std::vector<std::string> columns)
    : out_(out), columns_(std::move(columns)) {
  for (std::size_t i = 0; i < columns_.size(); ++i) out_ << (i > 0 ? "," : "") << columns_[i];
  out_ << '\n';
}

void CsvWriter::row(std::initializer_list<double> values) {
  if (values.size() != columns_.size()) {
    throw std::logic_error("CSV row of " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  }
  // The numbers straight into a buffer with room for the longest row (sized once), not
  // appended one by one: 34,000 numbers in a terrain run.
  line_.resize(values.size() * (kMaxNumberLength + 1));
  char* const first = line_.data();
  char* end = first;
  std::size_t column = 0;
  for (const double value : values) {
    if (!std::isfinite(value)) {
      throw std::runtime_error("CSV column " + columns_[column] + " would hold " +
                               formatNumber(value));
    }
    if (column++ > 0) *end++ = ',';
    end = writeNumber(end, value);
  }
  *end++ = '\n';
  out_.write(first, static_cast<std::streamsize>(end - first));
}

JsonWriter::JsonWriter(std::ostream& out) : out_(out), closers_("}") { out_ << '{'; }

std::string JsonWriter::formatNumber17(double value) {
  char digits[32];  // "-1.2345678901234567e-308" is 24 characters
  // + 0.0 turns -0 into 0, as in CSV.
  return std::string(digits, std::to_chars(digits, digits + sizeof digits, value + 0.0,
                                           std::chars_format::general, 17)
                                 .ptr);
}

void JsonWriter::writeQuoted(std::string_view text) {
  out_ << '"';
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out_ << '\\' << c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out_ << escaped;
    } else {
      out_ << c;
    }
  }
  out_ << '"';
}

void JsonWriter::beginElement(std::optional<std::string_view> key) {
  if (closers_.empty()) throw std::logic_error("JSON: writing after finish()");
  const bool in_object = closers_.back() == '}';
  if (in_object != key.has_value()) {
    throw std::logic_error(in_object ? "JSON: an object member needs a key"
                                     : "JSON: an array element takes no key");
  }
  out_ << (empty_ ? "\n" : ",\n") << std::string(2 * closers_.size(), ' ');
  if (key) {
    writeQuoted(*key);
    out_ << ": ";
  }
  empty_ = false;
}

void JsonWriter::open(std::optional<std::string_view> key, char bracket) {
  beginElement(key);
  out_ << bracket;
  closers_ += bracket == '{' ? '}' : ']';
  empty_ = true;
}

JsonWriter& JsonWriter::number(std::string_view key, double value) {
  if (!std::isfinite(value)) {
    throw std::runtime_error("JSON member " + std::string(key) + " would hold " +
                             formatNumber(value));
  }
  beginElement(key);
  out_ << formatNumber17(value);
  return *this;
}

JsonWriter& JsonWriter::numbers(std::string_view key, const std::vector<double>& values) {
  return numberArray(key, values);
}

JsonWriter& JsonWriter::numbers(const std::vector<double>& values) {
  return numberArray(std::nullopt, values);
}

JsonWriter& JsonWriter::numberArray(std::optional<std::string_view> key,
                                    const std::vector<double>& values) {
  for (const double value : values) {
    if (!std::isfinite(value)) {
      throw std::runtime_error("JSON member " + std::string(key.value_or("(array element)")) +
                               " would hold " + formatNumber(value));
    }
  }
  beginElement(key);
  out_ << '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    out_ << (i > 0 ? ", " : "") << formatNumber17(values[i]);
  }
  out_ << ']';
  return *this;
}

JsonWriter& JsonWriter::text(std::string_view key, std::string_view value) {
  beginElement(key);
  writeQuoted(value);
  return *this;
}

JsonWriter& JsonWriter::boolean(std::string_view key, bool value) {
  beginElement(key);
  out_ << (value ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::beginObject(std::string_view key) {
  open(key, '{');
  return *this;
}

JsonWriter& JsonWriter::beginArray(std::string_view key) {
  open(key, '[');
  return *this;
}

JsonWriter& JsonWriter::beginObject() {
  open(std::nullopt, '{');
  return *this;
}

JsonWriter& JsonWriter::end() {
  if (closers_.size() < 2) {
    throw std::logic_error(
        "JSON: end() without an open object or array (finish() closes the "
        "top-level object)");
  }
  if (!empty_) out_ << '\n' << std::string(2 * (closers_.size() - 1), ' ');
  out_ << closers_.back();
  closers_.pop_back();
  empty_ = false;
  return *this;
}

void JsonWriter::finish() {
  if (closers_.size() != 1) {
    throw std::logic_error(closers_.empty() ? "JSON: finish() called twice"
                                            : "JSON: finish() with an object or array still open");
  }
  out_ << (empty_ ? "}\n" : "\n}\n");
  closers_.clear();
}

}  // namespace spherical_robots::sphere_sim
