// The READ card's JSON form and rules (io/read_card.hpp): what the resume body, the store's column
// and the worker protocol read and write.
#include <gtest/gtest.h>

#include "io/restart/read_card.hpp"
#include "io/sections/run_limits.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

/// "pointer: detail" of every issue the card raises, or "" when it reads.
std::vector<std::string> issues(const json& card, ReadCardForm form = ReadCardForm::changes, bool gaps = true) {
  try {
    (void)read_card_from_json(card, form, gaps);
  } catch (const ModelError& e) {
    std::vector<std::string> out;
    for (const InputIssue& i : e.issues()) out.push_back(i.pointer + ": " + i.detail);
    return out;
  }
  return {};
}

TEST(ReadCard, ReadsTheChangesOfAResume) {
  const ResumeOptions card = read_card_from_json(
      json{{"tensile_schedule", {30.0, 3.0}}, {"max_iterations", 40}, {"extrapolation_factor", 0.25}},
      ReadCardForm::changes);
  EXPECT_EQ(card.tensile_schedule, (std::vector<double>{30.0, 3.0}));
  EXPECT_EQ(card.max_iterations, 40);
  EXPECT_EQ(card.extrapolation_factor, 0.25);
  EXPECT_TRUE(card.restart_schedule);  // a schedule given now starts afresh
  EXPECT_EQ(read_card_to_json(card, ReadCardForm::changes),
            (json{{"tensile_schedule", {30.0, 3.0}}, {"max_iterations", 40}, {"extrapolation_factor", 0.25}}));
  // The job resource shows max_iterations as the job's own, not among the resume settings.
  EXPECT_EQ(read_card_to_json(card, ReadCardForm::in_force),
            (json{{"tensile_schedule", {30.0, 3.0}}, {"extrapolation_factor", 0.25}}));
  EXPECT_EQ(read_card_to_json(ResumeOptions{}, ReadCardForm::changes), json::object());
}

TEST(ReadCard, EveryProblemIsNamedByItsPointerInTheRulesWords) {
  const std::string limit = std::to_string(max_iterations_limit);
  EXPECT_EQ(issues(json{{"max_iterations", 0}}),
            std::vector<std::string>{"/max_iterations: must be an integer from 1 to " + limit + ", got 0"});
  EXPECT_EQ(issues(json{{"max_iterations", max_iterations_limit + 1}}).size(), 1u);
  EXPECT_EQ(issues(json{{"max_iterations", 2.5}}).size(), 1u);
  EXPECT_EQ(issues(json{{"max_iterations", max_iterations_limit}}).size(), 0u);
  EXPECT_EQ(issues(json{{"extrapolation_factor", 1.0}}),
            std::vector<std::string>{"/extrapolation_factor: must be a number at least 0 and below 1, got 1.0"});
  EXPECT_EQ(issues(json{{"extrapolation_factor", 0.0}}).size(), 0u);
  EXPECT_EQ(issues(json{{"extrapolation_factor", -0.1}}).size(), 1u);
  EXPECT_EQ(issues(json{{"tensile_schedule", json::array()}}),
            std::vector<std::string>{"/tensile_schedule: must be a non-empty array of numbers > 0, got []"});
  EXPECT_EQ(issues(json{{"tensile_schedule", {5.0, 0.0, "x"}}}),
            (std::vector<std::string>{"/tensile_schedule/1: a tensile modulus must be a number > 0, got 0.0",
                                      "/tensile_schedule/2: a tensile modulus must be a number > 0, got \"x\""}));
  EXPECT_EQ(issues(json{{"restart_schedule", true}}),
            std::vector<std::string>{"/restart_schedule: unknown key \"restart_schedule\" (known: tensile_schedule, "
                                     "max_iterations, extrapolation_factor)"});
  EXPECT_EQ(issues(json::array()).size(), 1u);
  // Without gaps there is no schedule to change, nor anything to extrapolate.
  EXPECT_EQ(issues(json{{"tensile_schedule", {1.0}}, {"extrapolation_factor", 0.5}, {"max_iterations", 3}},
                   ReadCardForm::changes, false),
            (std::vector<std::string>{"/extrapolation_factor: the model has no gaps, so nothing to extrapolate",
                                      "/tensile_schedule: the model has no gaps, so it has no tensile schedule"}));
}

TEST(ReadCard, TheStoredFormKeepsWhetherTheScheduleStartsAfresh) {
  ResumeOptions card;
  card.tensile_schedule = std::vector<double>{7.0};
  card.max_iterations = 12;
  card.restart_schedule = false;
  const std::string text = stored_read_card_text(card);
  const ResumeOptions back = stored_read_card(text);
  EXPECT_EQ(back.tensile_schedule, card.tensile_schedule);
  EXPECT_EQ(back.max_iterations, 12);
  EXPECT_FALSE(back.extrapolation_factor.has_value());
  EXPECT_FALSE(back.restart_schedule);
  card.restart_schedule = true;
  EXPECT_TRUE(stored_read_card(stored_read_card_text(card)).restart_schedule);
  // A column written before any resume, or damaged, reads as no changes.
  for (const char* column : {"{}", "not json", "[1]", "{\"max_iterations\": \"x\"}"}) {
    const ResumeOptions none = stored_read_card(column);
    EXPECT_FALSE(none.tensile_schedule || none.max_iterations || none.extrapolation_factor) << column;
    EXPECT_FALSE(none.restart_schedule) << column;
  }
}

TEST(ReadCard, ALaterCardReplacesWhatItChanges) {
  ResumeOptions in_force;
  in_force.tensile_schedule = std::vector<double>{9.0};
  in_force.extrapolation_factor = 0.5;
  in_force.restart_schedule = false;
  ResumeOptions later;
  later.max_iterations = 30;
  in_force.apply(later);
  EXPECT_EQ(in_force.tensile_schedule, (std::vector<double>{9.0}));
  EXPECT_EQ(in_force.max_iterations, 30);
  EXPECT_FALSE(in_force.restart_schedule);
  later.tensile_schedule = std::vector<double>{4.0, 2.0};
  in_force.apply(later);
  EXPECT_EQ(in_force.tensile_schedule, later.tensile_schedule);
  EXPECT_TRUE(in_force.restart_schedule);
}

}  // namespace
}  // namespace saasgaps::io
