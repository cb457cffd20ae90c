#pragma once
/// Validators of what the API serves (ETags) and conditional GETs: a client that names the current
/// tag in If-None-Match gets 304, and the representation is neither read nor built again.

#include <httplib.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// FNV-1a, continued from `h`.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 1469598103934665603ULL);

/// A validator of a representation: FNV-1a of its bytes (and of what else selects it).
std::string entity_tag(std::string_view bytes, std::string_view variant = {});

/// A validator of a job's stored result without reading it: the result is written only by finish(),
/// which stamps finished_at (milliseconds) and counts the run in attempts.
std::string result_tag(JobStore& store, std::int64_t id, std::size_t size, std::string_view variant = {});

/// Sets a weak ETag and answers 304 when If-None-Match names it (RFC 9110 section 13.1.2: weak comparison,
/// "*" matches any).
bool not_modified(const httplib::Request& req, httplib::Response& res, const std::string& tag);

}  // namespace saasgaps::service
