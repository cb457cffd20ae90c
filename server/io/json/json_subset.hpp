#pragma once
/// Parsing a JSON document into a tree of only the members a reader needs. A plot of a 10^6-unknown
/// result reads a fraction of its 300 MB (a convergence plot: the history; a contour: each
/// element's id, nodes and one field of its 18 members), and a tree of the whole costs 1.6-1.9 GB.
///
/// nlohmann's own parser callback can drop members too, but its tree builder scans the parent
/// container for discarded values after every object it closes: quadratic in the length of an
/// array of objects (a contour plot of that result took minutes). This builder is one SAX pass,
/// linear in the text.

#include <functional>
#include <string_view>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// Whether to keep the member `key` of an object at `depth` (1: a member of the root object, 2: of
/// an object inside one of those, ...). `section` is the root member the object lies under ("" for
/// the root's own members).
using MemberFilter = std::function<bool(int depth, std::string_view section, std::string_view key)>;

/// The document with only the members `keep` accepts (everything when `keep` is empty). Text that is
/// not JSON throws nlohmann::json::parse_error, as nlohmann::json::parse does; repeated keys keep
/// the last value, as it does. A document nesting deeper than max_json_depth throws NestingTooDeep
/// (io/json_limits.hpp).
nlohmann::json parse_json_subset(std::string_view text, const MemberFilter& keep);

}  // namespace saasgaps::io
