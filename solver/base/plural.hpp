#pragma once
/// Counts in messages: "1 iteration", "3 iterations", "1 gap", "0 gaps".

#include <string>

namespace saasgaps {

/// The count with its noun, plural unless the count is 1 (nouns that take an s only).
std::string plural(long long count, const std::string& noun);

}  // namespace saasgaps
