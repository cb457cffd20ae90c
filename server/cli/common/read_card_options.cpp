#include "cli/common/read_card_options.hpp"

#include "cli/common/usage.hpp"
#include "io/restart/read_card.hpp"
#include "io/sections/run_limits.hpp"

namespace saasgaps::cli {

void add_read_card_options(CLI::App& command, ResumeOptions& changes, const std::string& schedule_note) {
  command.add_option("--max-iterations", changes.max_iterations, "Iteration limit (overrides the model's)")
      ->check(integer_rule(io::max_iterations_allowed, io::max_iterations_rule(), "INT in [1 - " + std::to_string(io::max_iterations_limit) + "]"));
  command.add_option("--schedule", changes.tensile_schedule,
                     "New tensile modulus schedule, absolute moduli, comma separated" + schedule_note)
      ->delimiter(',')
      ->check(number_rule(io::tensile_modulus_allowed, io::tensile_modulus_rule, "NUMBER > 0"));
  command.add_option("--extrapolation", changes.extrapolation_factor, "Extrapolation factor XFACT, 0 <= F < 1")
      ->check(number_rule(io::extrapolation_factor_allowed, io::extrapolation_factor_rule, "0 <= NUMBER < 1"));
}

}  // namespace saasgaps::cli
