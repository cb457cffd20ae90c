#pragma once
/// The database's schema as the migrations that build it, one version after another. PRAGMA
/// user_version records how far a database has come; opening the store applies the rest
/// (job_store_writability.cpp).

#include <vector>

namespace saasgaps::service {
namespace detail {

/// Schema versions, applied in order. A new version is a new entry at the end: a database records
/// only how many it has had, so an entry once released never changes.
extern const std::vector<const char*> migrations;

}  // namespace detail
}  // namespace saasgaps::service
