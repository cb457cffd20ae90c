#pragma once
/// Times as the service writes them (logs, the store's columns): UTC, ISO 8601 with milliseconds.

#include <chrono>
#include <string>

namespace saasgaps::service {

/// Current UTC time, ISO 8601 with milliseconds.
std::string utc_now();
/// A UTC time in the same format (text order is time order).
std::string utc_text(std::chrono::system_clock::time_point when);

}  // namespace saasgaps::service
