#include "io/restart/read_card.hpp"

#include <cstdint>

#include "io/json/json_pointer.hpp"
#include "io/json/json_text.hpp"
#include "io/model/model_reader.hpp"
#include "io/sections/run_limits.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {

using nlohmann::json;

bool max_iterations_allowed(long long n) { return n >= 1 && n <= max_iterations_limit; }
bool tensile_modulus_allowed(double e) { return e > 0.0; }
bool extrapolation_factor_allowed(double f) { return f >= 0.0 && f < 1.0; }

std::string max_iterations_rule() {
  return "must be an integer from 1 to " + std::to_string(max_iterations_limit);
}

namespace {

std::string refusal(const std::string& rule, const json& value) { return rule + ", got " + json_text(value); }

}  // namespace

ResumeOptions read_card_from_json(const json& value, ReadCardForm form, bool model_has_gaps) {
  std::vector<InputIssue> issues;
  ResumeOptions card;
  card.restart_schedule = form == ReadCardForm::changes;
  if (!value.is_object()) {
    throw ModelError(std::vector<InputIssue>{{"", "must be an object, like {\"max_iterations\": 40}, got " +
                                                      json_text(value)}},
                     "resume settings");
  }
  const bool with_limit = form != ReadCardForm::in_force;
  for (const auto& [key, member] : value.items()) {
    const std::string pointer = pointer_append("", key);
    if (key == "tensile_schedule") {
      if (!model_has_gaps) issues.push_back({pointer, no_gaps_schedule});
      if (!member.is_array() || member.empty()) {
        issues.push_back({pointer, refusal(tensile_schedule_rule, member)});
        continue;
      }
      std::vector<double> schedule;
      for (std::size_t i = 0; i < member.size(); ++i) {
        if (!member[i].is_number() || !tensile_modulus_allowed(member[i].get<double>())) {
          issues.push_back({pointer_append(pointer, i), "a tensile modulus " + refusal(tensile_modulus_rule, member[i])});
        } else {
          schedule.push_back(member[i].get<double>());
        }
      }
      card.tensile_schedule = std::move(schedule);
    } else if (key == "max_iterations" && with_limit) {
      // An integer beyond int64 reads as a double (not an integer) or wraps negative: out of range.
      if (!member.is_number_integer() || !max_iterations_allowed(member.get<std::int64_t>())) {
        issues.push_back({pointer, refusal(max_iterations_rule(), member)});
      } else {
        card.max_iterations = member.get<int>();
      }
    } else if (key == "extrapolation_factor") {
      if (!model_has_gaps) issues.push_back({pointer, no_gaps_extrapolation});
      if (!member.is_number() || !extrapolation_factor_allowed(member.get<double>())) {
        issues.push_back({pointer, refusal(extrapolation_factor_rule, member)});
      } else {
        card.extrapolation_factor = member.get<double>();
      }
    } else if (key == "restart_schedule" && form == ReadCardForm::stored) {
      if (!member.is_boolean()) {
        issues.push_back({pointer, refusal("must be true or false", member)});
      } else {
        card.restart_schedule = member.get<bool>();
      }
    } else {
      issues.push_back({pointer, "unknown key \"" + key + "\" (known: tensile_schedule, " +
                                     (with_limit ? "max_iterations, " : "") + "extrapolation_factor" +
                                     (form == ReadCardForm::stored ? ", restart_schedule" : "") + ")"});
    }
  }
  if (!issues.empty()) throw ModelError(std::move(issues), "resume settings");
  return card;
}

json read_card_to_json(const ResumeOptions& card, ReadCardForm form) {
  json j = json::object();
  if (card.tensile_schedule) j["tensile_schedule"] = *card.tensile_schedule;
  if (card.max_iterations && form != ReadCardForm::in_force) j["max_iterations"] = *card.max_iterations;
  if (card.extrapolation_factor) j["extrapolation_factor"] = *card.extrapolation_factor;
  if (form == ReadCardForm::stored) j["restart_schedule"] = card.restart_schedule;
  return j;
}

std::string stored_read_card_text(const ResumeOptions& card) {
  return json_text(read_card_to_json(card, ReadCardForm::stored));
}

ResumeOptions stored_read_card(const std::string& text) {
  try {
    return read_card_from_json(parse_document(text), ReadCardForm::stored);
  } catch (const ModelError&) {
    // Not JSON, or not the stored form: damage, read as no changes.
    ResumeOptions none;
    none.restart_schedule = false;
    return none;
  }
}

}  // namespace saasgaps::io
