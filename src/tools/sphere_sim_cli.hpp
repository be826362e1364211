#pragma once
// The command-line machinery every sphere_sim subcommand shares (DESIGN.md, "sphere_sim"):
// dispatch, option tables with --help, option values that may begin with '-', numbers that
// parse nan/inf and then reject them, comma-separated lists, exit statuses, CSV rows and JSON
// objects at full precision and output files that appear only when complete.
//
// A subcommand is a table of OptionSpec plus a run function; see terrain_command.cpp.

#include <cstddef>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace spherical_robots::sphere_sim {

/// Process exit statuses, the same for every subcommand.
enum ExitStatus : int {
  kSuccess = 0,
  kInternalError = 1,  ///< a bug (e.g. std::logic_error), not the user's fault
  kUsageError = 2,     ///< unknown option, malformed value, missing required option
  kNoSolution = 3,     ///< well-posed problem without a solution; the output file is written
  kInvalidInput = 4,   ///< invalid or degenerate input; one-line error, no output file
};

/// A command line that does not follow the subcommand's syntax (exit 2, usage on stderr).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A syntactically fine command line whose values make no sense (exit 4), e.g. a non-finite number
/// or a negative step. The core's std::invalid_argument is treated the same way.
class InvalidInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One row of a subcommand's option table.
struct OptionSpec {
  std::string name;           ///< without the leading "--", e.g. "duration"
  std::string value_name;     ///< placeholder in the usage line, e.g. "SECONDS"; empty for a flag
  std::string help;           ///< meaning and units, for --help
  std::string default_value;  ///< used when the option is absent; empty: no default
  bool required = false;      ///< absent and required is a usage error
  std::vector<std::string> choices;  ///< if not empty, the only values accepted
};

/// The options of one invocation, checked against the table: every name is known, every value
/// present, every choice valid, every required option given. Typed access parses on demand.
class ParsedOptions {
 public:
  ParsedOptions(std::string command, std::map<std::string, std::string> values,
                std::map<std::string, std::string> defaults);

  /// Given on the command line (defaults do not count).
  bool given(const std::string& name) const;
  /// The value, or the table's default. @throw std::logic_error if the option has neither.
  const std::string& text(const std::string& name) const;
  /// A flag's presence.
  bool flag(const std::string& name) const { return given(name); }
  /// The value as a finite double. @throw UsageError if it is not a number, InvalidInput if it
  /// is nan, inf or out of a double's range.
  double number(const std::string& name) const;
  /// The value as an int (counts, seeds). @throw as number(), and UsageError if it is not a whole
  /// number within an int's range.
  int integer(const std::string& name) const;
  /// A comma-separated list of finite doubles; count 0 accepts any length >= 1.
  /// @throw UsageError on a malformed element or a wrong count, InvalidInput on a non-finite one.
  std::vector<double> numberList(const std::string& name, std::size_t count = 0) const;
  /// A ';'-separated list of such lists (joint lists: "0.1,-0.2;0.3,0"), each of count numbers
  /// (0: any length >= 1). @throw as numberList(), naming the group.
  std::vector<std::vector<double>> numberGroups(const std::string& name,
                                                std::size_t count = 0) const;

 private:
  std::string command_;
  std::map<std::string, std::string> values_;
  std::map<std::string, std::string> defaults_;
};

/// A subcommand: its table and what it does. run returns kSuccess or kNoSolution, writes its
/// summary to out, and throws UsageError, InvalidInput or std::invalid_argument on bad input.
struct Subcommand {
  std::string name;         ///< e.g. "terrain"
  std::string summary;      ///< one line for `sphere_sim --help`
  std::string description;  ///< printed after the options by `sphere_sim NAME --help`
  std::vector<OptionSpec> options;
  std::function<int(const ParsedOptions& options, std::ostream& out)> run;
};

/// Checks args (everything after the subcommand name) against the table. A token "--name"
/// names an option; if the option takes a value, the next token is its value whatever it
/// starts with, so negative numbers need no quoting. "--name=value" works as well.
/// @throw UsageError on an unknown, repeated or incomplete option, a bad choice, a positional
/// argument or a missing required option.
ParsedOptions parseOptions(const Subcommand& command, const std::vector<std::string>& args);

/// `sphere_sim NAME --help`: usage line, options with defaults, description.
void printHelp(const Subcommand& command, std::ostream& out);

/// Runs sphere_sim with args (argv without the program name): dispatches to the subcommand,
/// prints help, maps errors to exit statuses and messages on err. Returns the exit status.
int runSphereSim(const std::vector<Subcommand>& commands, const std::vector<std::string>& args,
                 std::ostream& out, std::ostream& err);

/// Rows of an option table by kind, so that a row states only what sets it apart: an optional
/// option taking a value (default_value used when it is absent; empty: no default), a required
/// one, and a flag.
OptionSpec optionalOption(std::string name, std::string value_name, std::string help,
                          std::string default_value = "");
OptionSpec requiredOption(std::string name, std::string value_name, std::string help);
OptionSpec flagOption(std::string name, std::string help);

/// The `--out FILE` option every subcommand has.
OptionSpec outOption(const std::string& what);
/// The `--config DIR` option of subcommands that read config/ and urdf/.
OptionSpec configOption();
/// The directory holding config/ and urdf/: --config if given, else the package's share directory.
std::string configDirectory(const ParsedOptions& options);

/// span / step [s] as a whole number of steps (a duration or a log period in plant steps); `what`
/// names the options for the message. @throw InvalidInput if it is more than 1e9 steps (a typo,
/// not a batch run) or not a whole number.
long wholeSteps(double span, double step, const std::string& what);

/// The radius [m] of the sphere of `link` in the URDF at path. @throw InvalidInput naming the path.
double radiusFromUrdf(const std::string& path, const std::string& link);

/// An output file that appears under its name only when committed: it is written to a temporary
/// file beside it and renamed, so a run that fails half-way (exit 4) leaves no file behind. A path
/// that names a symbolic link is resolved first (the link stays a link). A path that exists and is
/// not a regular file (/dev/null, /dev/stdout, a named pipe) is written directly: renaming a file
/// over it would replace the device or pipe itself.
class OutputFile {
 public:
  /// @throw InvalidInput naming the path if it (a device or pipe) or the temporary file cannot be
  /// opened.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return stream_; }
  /// Flushes, closes and renames into place. @throw std::runtime_error naming the path on a write
  /// error.
  void commit();

 private:
  std::string path_;          ///< as given
  std::string rename_path_;   ///< path_, or the file its symbolic link names; empty: written directly
  std::string temporary_path_;
  std::unique_ptr<char[]> buffer_;  // a large buffer: rows are written without per-row flushes
  std::ofstream stream_;
  bool committed_ = false;
};

/// The shortest decimal text that reads back as the same double (full precision, no noise
/// digits: 0.1 prints as "0.1").
std::string formatNumber(double value);

/// CSV output: a header row, then rows of numbers as formatNumber writes them (no blanks, no text).
class CsvWriter {
 public:
  /// Writes the header. The stream must outlive the writer.
  CsvWriter(std::ostream& out, std::vector<std::string> columns);
  /// @throw std::logic_error if the number of values is not the number of columns,
  /// std::runtime_error naming the column if a value is not finite.
  void row(std::initializer_list<double> values);
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::ostream& out_;
  std::vector<std::string> columns_;
  std::string line_;  // reused for every row, so writing allocates nothing after the first
};

/// JSON output (DESIGN.md): one object, written as it is built, keys in the order given, two-space
/// indentation, numbers as JSON numbers with 17 significant digits (−0 written as 0), arrays of
/// numbers on one line. Misuse (a key inside an array, none inside an object, unbalanced
/// begin/end, writing after finish) is a std::logic_error; the stream must outlive the writer.
class JsonWriter {
 public:
  /// Writes the opening brace of the top-level object.
  explicit JsonWriter(std::ostream& out);

  /// A number member of the current object. @throw std::runtime_error naming the key if the value
  /// is not finite (JSON has no nan or inf).
  JsonWriter& number(std::string_view key, double value);
  /// A member holding an array of numbers, e.g. "omega": [0.5, -1, 0]. @throw as number().
  JsonWriter& numbers(std::string_view key, const std::vector<double>& values);
  /// An array of numbers as the next element of the current array (rows of a matrix).
  JsonWriter& numbers(const std::vector<double>& values);
  JsonWriter& text(std::string_view key, std::string_view value);
  JsonWriter& boolean(std::string_view key, bool value);
  /// Opens an object or array member of the current object; end() closes it.
  JsonWriter& beginObject(std::string_view key);
  JsonWriter& beginArray(std::string_view key);
  /// Opens an object as the next element of the current array.
  JsonWriter& beginObject();
  /// Closes the innermost open object or array (not the top-level object: see finish()).
  JsonWriter& end();
  /// Closes the top-level object and ends the line. @throw std::logic_error if anything else is
  /// still open.
  void finish();

  /// value with 17 significant digits, as the writer puts it (e.g. 0.1 -> 0.10000000000000001).
  static std::string formatNumber17(double value);

 private:
  /// Starts a new element: comma, newline, indentation, and "key": in an object.
  void beginElement(std::optional<std::string_view> key);
  void open(std::optional<std::string_view> key, char bracket);
  JsonWriter& numberArray(std::optional<std::string_view> key, const std::vector<double>& values);
  void writeQuoted(std::string_view text);

  std::ostream& out_;
  std::string closers_;  // one ']' or '}' per open container, innermost last
  bool empty_ = true;    // the innermost container has no element yet
};

}  // namespace spherical_robots::sphere_sim
