#include "cli/read_card_options.hpp"

#include "cli/usage.hpp"
#include "io/run_limits.hpp"

namespace saasgaps::cli {

void add_read_card_options(CLI::App& command, ReadCardChanges& changes, const std::string& schedule_note) {
  command.add_option("--max-iterations", changes.max_iterations, "Iteration limit (overrides the model's)")
      ->check(integer_range(1, io::max_iterations_limit));
  command.add_option("--schedule", changes.tensile_schedule,
                     "New tensile modulus schedule, absolute moduli, comma separated" + schedule_note)
      ->delimiter(',')
      ->check(positive_number());
  command.add_option("--extrapolation", changes.extrapolation_factor, "Extrapolation factor XFACT, 0 <= F < 1")
      ->check(fraction_below_one());
}

}  // namespace saasgaps::cli
