#pragma once
/// The contact solvers' state between solves, as plain data: what a restart state carries for
/// exact contact (contact/exact_contact.hpp) and for Coulomb friction (contact/frictional_contact.hpp).

#include <cstdint>
#include <vector>

namespace saasgaps {

/// What the next contact solve starts from and what the last one found (part of the restart state).
struct ContactState {
  std::vector<double> force;          ///< lambda_i >= 0 per pair (force units: the nodal load it puts on each side)
  std::vector<std::uint8_t> active;   ///< 1: pair i was enforced at g_i = 0
  [[nodiscard]] bool empty() const { return active.empty(); }
};

enum class SlipState : std::uint8_t { open = 0, stick = 1, slip = 2 };

/// The friction state of every contact point: what a restart state must carry. `previous` and
/// `slip` change only in finish_increment (the increment's history); the rest is the last solve's
/// answer and the next solve's warm start (the next increment's, or the next iteration's within an
/// increment, e.g. of a plasticity secant loop).
struct FrictionState {
  std::vector<std::uint8_t> state;       ///< SlipState per point
  std::vector<std::int8_t> direction;    ///< slip: s = sign of the increment's slip (+1, -1); else 0
  std::vector<double> normal_force;      ///< lambda_n >= 0 (force: the nodal load it puts on each side)
  std::vector<double> tangential_force;  ///< lambda_t on side b along t, |lambda_t| <= mu lambda_n
  std::vector<double> position;          ///< h_i(u) of the last solve (length)
  std::vector<double> previous;          ///< h_i at the end of the last finished increment (0 at the start)
  std::vector<double> slip;              ///< accumulated |slip| over the finished increments (length)

  [[nodiscard]] bool empty() const { return state.empty(); }
  [[nodiscard]] std::size_t size() const { return state.size(); }
};

}  // namespace saasgaps
