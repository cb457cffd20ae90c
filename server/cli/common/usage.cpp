#include "cli/common/usage.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>

#include "cli/common/http_client.hpp"
#include "io/mesher/gmsh_mesh.hpp"
#include "solver/base/errors.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps::cli {

namespace {

/// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
/// neighbours each cost 1 ("slove" is one step from "solve"). O(|a| |b|) on words of a few letters.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

bool is_number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

/// The command whose arguments were being read when parsing stopped: the deepest subcommand seen.
CLI::App* command_in_use(CLI::App& app) {
  CLI::App* command = &app;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  return command;
}

/// "saasgaps" or "saasgaps solve".
std::string full_name(const CLI::App* command) {
  std::string name = command->get_name();
  for (const CLI::App* parent = command->get_parent(); parent != nullptr; parent = parent->get_parent()) {
    name = parent->get_name() + " " + name;
  }
  return name;
}

std::vector<std::string> subcommand_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* sub : command.get_subcommands({})) names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& known) {
  const std::optional<std::string> guess = nearest(word, known);
  return guess ? "; did you mean '" + *guess + "'?" : "";
}

/// What went wrong, in the user's words: the mistyped command or option by name, else CLI11's own
/// sentence (a missing argument, a value out of range, an extra argument).
std::string describe_mistake(CLI::App& command, const std::vector<std::string>& arguments, const CLI::ParseError& error) {
  // Arguments that belong to `command`: those after its name (all of them for the program itself).
  auto first = arguments.begin();
  if (command.get_parent() != nullptr) {
    first = std::find(arguments.begin(), arguments.end(), command.get_name());
    if (first != arguments.end()) ++first;
  }
  const std::vector<std::string> known_options = option_names(command);
  for (auto it = first; it != arguments.end(); ++it) {
    if (*it == "--") break;
    if (it->size() < 2 || (*it)[0] != '-' || is_number(*it)) continue;
    const std::string name = it->substr(0, it->find('='));
    // "-q" and "-o" may be bundled or carry their value ("-ofile"): only the first letter names the option.
    const std::string short_name = (*it)[1] == '-' ? name : it->substr(0, 2);
    if (std::find(known_options.begin(), known_options.end(), short_name) == known_options.end()) {
      return "unknown option '" + short_name + "'" + did_you_mean(short_name, known_options);
    }
  }
  if (command.get_parent() == nullptr) {
    const std::vector<std::string> commands = subcommand_names(command);
    const auto word = std::find_if(first, arguments.end(), [](const std::string& a) { return !a.empty() && a[0] != '-'; });
    if (word == arguments.end()) return "a command is required (" + CLI::detail::join(commands, ", ") + ")";
    if (std::find(commands.begin(), commands.end(), *word) == commands.end()) {
      return "unknown command '" + *word + "'" + did_you_mean(*word, commands);
    }
  }
  return error.what();
}

}  // namespace

std::optional<std::string> nearest(const std::string& word, const std::vector<std::string>& known) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : known) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  if (best) return best;
  // A unique prefix: "exp" is "export-vtu".
  std::vector<std::string> prefixed;
  for (const std::string& candidate : known) {
    if (word.size() >= 2 && candidate.rfind(word, 0) == 0) prefixed.push_back(candidate);
  }
  if (prefixed.size() == 1) return prefixed.front();
  return std::nullopt;
}

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::Success& done) {
    // --help prints the help of the command it follows; --version the version.
    return app.exit(done);
  } catch (const CLI::ParseError& error) {
    CLI::App* command = command_in_use(app);
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    // One line and where to look: the whole help would bury the mistake under fifty lines.
    std::cerr << full_name(command) << ": " << describe_mistake(*command, arguments, error) << "\n"
              << "run '" << full_name(command) << " --help' for "
              << (command->get_parent() != nullptr ? "its options" : "the commands") << '\n';
    return exit_code::usage;
  }
}

int run_command(const std::function<int()>& command, const std::string& document) {
  try {
    return command();
  } catch (const ProblemError& e) {
    std::cerr << "error: " << e.title() << " (HTTP " << e.status() << ")" << (e.detail().empty() ? "" : ": " + e.detail())
              << '\n';
    for (const ProblemIssue& issue : e.errors()) {
      std::cerr << (issue.pointer.empty() ? "(document)" : issue.pointer) << ": " << issue.detail << '\n';
    }
    return e.status() == 422 ? exit_code::bad_model : exit_code::failure;
  } catch (const UsageError& e) {
    std::cerr << "saasgaps " << e.what() << '\n';
    return exit_code::usage;
  } catch (const ModelError& e) {
    std::cerr << "invalid " << document << ": " << plural(static_cast<long long>(e.issues().size()), "error") << '\n';
    for (const InputIssue& issue : e.issues()) {
      std::cerr << (issue.pointer.empty() ? "(document)" : issue.pointer) << ": " << issue.detail << '\n';
    }
    return exit_code::bad_model;
  } catch (const io::MeshTooLarge& e) {
    // A mesh over the limits is refused like a bad assembly: the input is at fault.
    std::cerr << "invalid " << document << ": 1 error\n/mesh: " << e.what() << '\n';
    return exit_code::bad_model;
  } catch (const SingularModelError& e) {
    // A mechanism is a defect of the model (the model must be restrained).
    std::cerr << "invalid model: " << e.what() << '\n';
    return exit_code::bad_model;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return exit_code::failure;
  }
}

CLI::Validator number_rule(const std::function<bool(double)>& allowed, const std::string& rule,
                           const std::string& type_name) {
  return CLI::Validator(
      [allowed, rule](std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || !allowed(value)) {
          return rule + ", got \"" + text + "\"";
        }
        return {};
      },
      type_name);
}

CLI::Validator integer_rule(const std::function<bool(long long)>& allowed, const std::string& rule,
                            const std::string& type_name) {
  return CLI::Validator(
      [allowed, rule](std::string& text) -> std::string {
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || !allowed(value)) {
          return rule + ", got \"" + text + "\"";
        }
        return {};
      },
      type_name);
}

CLI::Validator integer_range(long long low, long long high) {
  return integer_rule([low, high](long long value) { return value >= low && value <= high; },
                      "must be an integer from " + std::to_string(low) + " to " + std::to_string(high),
                      "INT in [" + std::to_string(low) + " - " + std::to_string(high) + "]");
}

}  // namespace saasgaps::cli
