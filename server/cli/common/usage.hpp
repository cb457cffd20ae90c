#pragma once
/// The conventions every saasgaps subcommand shares, in one place: the exit codes, how a command line
/// that cannot be parsed is reported (the mistake, the nearest known command or option, and the help
/// of the command concerned), and how exceptions become exit codes. A new subcommand registered on
/// the CLI::App gets all of it without code of its own. docs/cli.md documents the codes.

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace saasgaps::cli {

/// A command line that parsed but does not fit what it names (an option the model cannot use):
/// reported like a parse error, "saasgaps <what>" (what names the command and option), exit code 64.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Exit codes. 0-3 are the contract of `solve` (docs/cli.md, "Exit codes"); 64 is EX_USAGE of BSD's sysexits.h,
/// kept apart from 2 so that a script can tell "this model is bad" from "this command line is".
namespace exit_code {
inline constexpr int ok = 0;             ///< converged, valid, written
inline constexpr int failure = 1;        ///< any other failure: a file that cannot be read or written, ...
inline constexpr int bad_model = 2;      ///< the model document is invalid or not restrained
inline constexpr int not_converged = 3;  ///< the run stopped before converging; it can be resumed
inline constexpr int usage = 64;         ///< the command line itself is wrong
}  // namespace exit_code

/// Parses the command line into `app`. Returns an exit code when the program should end here:
/// 0 after --help or --version (printed to stdout), exit_code::usage after a usage error (one line
/// on stderr naming the mistake, then where the help is: "run 'saasgaps solve --help' for its
/// options"). Returns nothing when a command should run.
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv);

/// The known word nearest to `word` (edit distance, at most a third of its length, or a prefix),
/// or nothing. "solv" -> "solve", "--max-iteration" -> "--max-iterations".
std::optional<std::string> nearest(const std::string& word, const std::vector<std::string>& known);

/// Runs a command and turns what it throws into an exit code, with the message on stderr:
/// ModelError and SingularModelError 2 (every issue with its JSON Pointer, under "invalid
/// `document`: N errors"); a service's refusal (ProblemError, cli/client/http_client.hpp) its title,
/// detail and every error's pointer, 2 for a 422 (an invalid model or resume body), else 1;
/// anything else 1.
int run_command(const std::function<int()>& command, const std::string& document = "model");

/// A validator of a number by a rule (e.g. io/restart/read_card.hpp's): `allowed` decides; a refusal says
/// `rule` and the text ("must be a number > 0, got \"abc\""). type_name shows in the help.
CLI::Validator number_rule(const std::function<bool(double)>& allowed, const std::string& rule,
                           const std::string& type_name);

/// The same for integers.
CLI::Validator integer_rule(const std::function<bool(long long)>& allowed, const std::string& rule,
                            const std::string& type_name);

/// A validator for integers in [low, high] whose message names the value.
CLI::Validator integer_range(long long low, long long high);

}  // namespace saasgaps::cli
