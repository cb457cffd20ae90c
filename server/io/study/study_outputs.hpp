#pragma once
/// A study's outputs: a named field of a result document reduced to one number.
///
/// `of` is "SECTION.KEY" (or "SECTION.KEY.SUBKEY"), read from the result document by name, so a
/// field a later result gains is reduced without new code once its name is in the table below:
///   - an array section (`nodes`, `elements`, `gaps`, `reactions`, `set_reactions`) gives KEY of
///     each item;
///   - `contact` gives KEY of each contact point of each pair (`contact.pressure`, `contact.shear`,
///     `contact.gap`, `contact.slip`), or of the pair itself (`contact.force.fz`);
///   - an object section (`reaction_sum`, `error_estimate`) gives its member KEY.
/// `elements` / `nodes` keep the items with those ids (`reactions` items by their `node`), `pair`
/// the contact pair whose surfaces are [A, B], `set` the set_reactions item of that node set (the
/// summed support reactions of a named set: a push-out force). max, min, sum or mean of what is left; no value at
/// all (an empty selection, a field the result lacks) is an OutputError naming what is missing.

#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/study/study_document.hpp"

namespace saasgaps::io {

/// An output that cannot be computed from a result (the point fails with this message).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Empty when `of` is a field this program knows; otherwise why not, listing the known fields
/// of its section (or the sections).
std::string unknown_output_field(std::string_view of);

/// Whether a selection (`elements`, `nodes`, `pair`) applies to the field's section; empty when it
/// does, otherwise why not.
std::string selection_problem(const StudyOutput& output);

/// The output's value on a result document.
double reduce_output(const nlohmann::json& result, const StudyOutput& output);

}  // namespace saasgaps::io
