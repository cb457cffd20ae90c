#pragma once
/// What a worker and the service say to each other (docs/cluster.md, "Worker protocol"). Bodies are
/// CBOR maps, so restart states travel as the bytes the store keeps, not as base64 or JSON numbers:
///   GET  /v1/jobs/{id}/work              -> {job, attempt, model, state: bytes|null, settings}
///   POST /v1/jobs/{id}/work/iterations   <- {iteration, row, state: bytes}   -> JSON {stop}
///   POST /v1/jobs/{id}/work/thermal      <- {index, row}                     -> 204
///   POST /v1/jobs/{id}/work/finish       <- {state, result?, message?, error?, model_digest}
///   POST /v1/jobs/{id}/lease             -> JSON {attempt, secret}
/// The lease request carries the run's single-use ticket in the Saasgaps-Ticket header,
/// "ATTEMPT:TICKET" (passed by the Slurm executor in $SAASGAPS_TICKET); every other request carries
/// the lease it was granted in the Saasgaps-Lease header, "ATTEMPT:SECRET". The routes exist only on
/// a service with the Slurm executor.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "service/runs/job_execution.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service::worker_protocol {

inline constexpr const char* lease_header = "Saasgaps-Lease";
inline constexpr const char* ticket_header = "Saasgaps-Ticket";
inline constexpr const char* cbor_type = "application/cbor";

std::string format_lease(const Lease& lease);
/// "ATTEMPT:SECRET" with ATTEMPT >= 1 and a non-empty secret; nothing otherwise. Tickets read alike.
std::optional<Lease> parse_lease(std::string_view text);

struct Work {
  std::int64_t job = 0;
  int attempt = 0;
  RunInput input;
};
std::string encode_work(const ClaimedJob& claimed);
Work decode_work(const std::string& body);

struct Iteration {
  int iteration = 0;
  std::string row;
  std::vector<std::uint8_t> state;
};
std::string encode_iteration(int iteration, const std::string& row, const std::vector<std::uint8_t>& state);
Iteration decode_iteration(const std::string& body);

/// A thermal history row (io/thermal_row_json.hpp) and its index in the run.
struct ThermalRow {
  int index = 0;
  std::string row;
};
std::string encode_thermal(int index, const std::string& row);
ThermalRow decode_thermal(const std::string& body);

struct Finish {
  JobState state = JobState::failed;
  std::optional<std::string> result, message, error;
  /// model_digest of the model the run solved (io/state_codec.hpp): must be the job's model's.
  std::string model_digest;
};
std::string encode_finish(const Finish& finish);
Finish decode_finish(const std::string& body);

/// A body that does not decode: std::invalid_argument naming the field. A body (or the JSON text of
/// a row or result in it) nesting deeper than io::max_json_depth: io::NestingTooDeep.

/// Fingerprint of a request body (io::Fingerprint): tells a retried finish from another one.
std::string body_digest(const std::string& body);

}  // namespace saasgaps::service::worker_protocol
