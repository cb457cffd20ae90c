#pragma once
/// The report's READ card (ResumeOptions, solver/analysis.hpp) outside the solver: the rule of each
/// of its values, said once, and its JSON form, read and written once. Every way in uses these: the
/// resume body (POST /v1/jobs/{id}/resume), the command line (`solve --resume`, `resume`), the
/// service's store (the jobs.settings column) and the worker protocol.
///
/// JSON form: {"tensile_schedule": [E1, E2, ...], "max_iterations": N, "extrapolation_factor": F},
/// every member optional; the stored form adds "restart_schedule" (bool).

#include <nlohmann/json.hpp>

#include <string>

#include "solver/state/resume_options.hpp"

namespace saasgaps::io {

/// The rules. Each predicate decides; its wording ("must be ...") is what every refusal says,
/// followed by ", got " and the value.
[[nodiscard]] bool max_iterations_allowed(long long n);   ///< 1 <= n <= max_iterations_limit
[[nodiscard]] bool tensile_modulus_allowed(double e);     ///< e > 0
[[nodiscard]] bool extrapolation_factor_allowed(double f);  ///< 0 <= f < 1
/// "must be an integer from 1 to 100000" (io::max_iterations_limit).
[[nodiscard]] std::string max_iterations_rule();
inline constexpr const char* tensile_modulus_rule = "must be a number > 0";
inline constexpr const char* tensile_schedule_rule = "must be a non-empty array of numbers > 0";
inline constexpr const char* extrapolation_factor_rule = "must be a number at least 0 and below 1";
/// Why a model without gaps takes neither a schedule nor a factor (said by every way in).
inline constexpr const char* no_gaps_schedule = "the model has no gaps, so it has no tensile schedule";
inline constexpr const char* no_gaps_extrapolation = "the model has no gaps, so nothing to extrapolate";

/// Which members a JSON form holds.
enum class ReadCardForm {
  changes,   ///< the three changes a resume makes (the resume body): no restart_schedule
  in_force,  ///< the job resource's resume_settings: schedule and factor (max_iterations is the job's own)
  stored,    ///< everything, restart_schedule included (the store's column, the worker protocol)
};

/// Reads the JSON form: every problem is an InputIssue with its JSON Pointer and the rule's wording,
/// thrown together as one ModelError; an unknown member is one too. Without gaps
/// (model_has_gaps = false), a schedule or factor is refused. A card read in form `changes` starts a
/// given schedule afresh (restart_schedule = true); the stored form says itself (false when absent).
[[nodiscard]] ResumeOptions read_card_from_json(const nlohmann::json& value, ReadCardForm form,
                                                bool model_has_gaps = true);

/// The JSON form: the members given (see ReadCardForm), an empty object when none.
[[nodiscard]] nlohmann::json read_card_to_json(const ResumeOptions& card, ReadCardForm form);

/// The stored form as text, and back. The reading does not fail: a damaged column (not written by
/// stored_read_card_text) reads as no changes, rather than making the job unreadable.
[[nodiscard]] std::string stored_read_card_text(const ResumeOptions& card);
[[nodiscard]] ResumeOptions stored_read_card(const std::string& text);

}  // namespace saasgaps::io
