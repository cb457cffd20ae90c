#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

ElementMatrices element_matrices(const ElementData& e) { return family(e.type).matrices(e); }

ElementStates element_states(const ElementData& e, std::span<const double> u) { return family(e.type).states(e, u); }

ElementState element_state(const ElementData& e, std::span<const double> u) { return element_states(e, u).centre; }

ElementVector internal_forces(const ElementMatrices& m, const ElementVector& u) {
  const Eigen::Index n = m.K.rows();
  if (n <= 8) {
    Mat8 K = Mat8::Zero();
    K.topLeftCorner(n, n) = m.K.selfadjointView<Eigen::Upper>();
    Vec8 u8 = Vec8::Zero();
    Vec8 f8 = Vec8::Zero();
    u8.head(n) = u;
    f8.head(n) = m.f;
    const Vec8 internal = K * u8 - f8;
    return internal.head(n);
  }
  const ElementMatrix K = m.K.selfadjointView<Eigen::Upper>();
  return K * u - m.f;
}

}  // namespace saasgaps
