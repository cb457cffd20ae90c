#pragma once
/// The two ways JobStore::open_result reads a stored result in pieces: through a blob handle on a
/// connection of its own, or, on a read-only store, from its text read whole.

#include <cstdint>
#include <memory>
#include <string>

#include "service/store/job_store.hpp"
#include "service/store/sqlite.hpp"

namespace saasgaps::service {
namespace detail {

/// The result of job `id` through its blob handle on `connection`, which it keeps open.
std::unique_ptr<JobStore::StoredResult> blob_result(std::unique_ptr<Connection> connection, std::int64_t id);
/// A result already read whole.
std::unique_ptr<JobStore::StoredResult> text_result(std::string text);

}  // namespace detail
}  // namespace saasgaps::service
