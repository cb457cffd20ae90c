#pragma once
/// The solver's result-affecting version: the one number a cached result is keyed by besides its
/// model (docs/studies.md, "The result cache").
///
/// The rule: bump it in the same commit as any change that can change a single digit of any result
/// document for some model (a kernel, a default, an iteration rule, the result writer's numbers or
/// fields), and never for anything else (a faster path that gives the same bits, the service, the
/// CLI, the release string). Every cache entry written under another value is then a miss, never a
/// stale hit; the release string is not used because a hash that moves with every release throws
/// away every cached result at every upgrade, even when nothing changed.

namespace saasgaps {

inline constexpr int result_version = 3;

}  // namespace saasgaps
