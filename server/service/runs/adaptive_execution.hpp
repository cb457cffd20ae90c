#pragma once
/// One run of an adaptive job (an uploaded assembly with `adapt`, docs/http-api.md) in the service's
/// own worker pool: the adaptive loop (io/import/adaptive_loop.hpp) over the stored assembly and its
/// files, each cycle committed (its `adaptation` row, the sizes it asked for, an `adapt_cycle`
/// event) before the next one meshes, the last cycle's result (with `adaptation`) as the job's.
///
/// A run that starts on a job with stored cycles (a resume, or a restart after a server died)
/// goes on after the last cycle that asked for sizes: a cycle stored without them (the last, whose
/// result was not yet committed) is meshed and solved again. A cancel or a shutdown stops the cycle
/// being solved at its next iteration boundary (cancelled, or interrupted to resume after restart);
/// the cycles committed stay. Iterations of the cycles' solves are not stored (their numbers
/// restart in every cycle): the cycles are the job's progress.

#include <atomic>

#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"
#include "solver/lac/ordering_cache.hpp"

namespace saasgaps::service {

/// Runs the claimed adaptive job to its end, committing into `store` and waking `hub`'s listeners.
/// Failures end the job as failed (a failure to record even that is logged).
void execute_adaptive_run(JobStore& store, EventHub& hub, const ClaimedJob& claimed, const AdaptiveInput& input,
                          const std::atomic<bool>& shutting_down, const OrderingCache* ordering_cache = nullptr);

}  // namespace saasgaps::service
