#pragma once
/// The limits on a run's settings that every way in checks alike: the model's
/// `solver.max_iterations` (io/section_reader.cpp, so `validate`, `solve` and POST /v1/jobs), the
/// command line's `--max-iterations` and `--stop-after`, and the resume body's `max_iterations`
/// (service/http_api.cpp, `saasgaps resume`). docs/model.md, docs/cli.md and
/// schemas/{model.schema,openapi}.json quote the same number.

namespace saasgaps::io {

/// The largest iteration limit a run may have. An iteration is a full linear solve; 100,000 of them
/// is far beyond any run that converges (the report's problems take 5 to 30), while a limit like
/// 10^9 only lets a run that never converges hold a worker forever.
inline constexpr int max_iterations_limit = 100000;

/// The most increments one load step may have (`steps[k].increments`): each increment is at least
/// one full linear solve, so this is already far beyond a run that finishes in reasonable time.
inline constexpr int max_increments_limit = 100000;

/// The most time steps a transient thermal run may take (thermal.end_time / thermal.time_step):
/// each is a solve with the factorization reused, so 10^6 already takes minutes on a large mesh.
inline constexpr double max_time_steps_limit = 1.0e6;

}  // namespace saasgaps::io
