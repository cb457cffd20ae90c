#include "solver/thermal/conduction_loads.hpp"

#include <cassert>

namespace saasgaps {

void ConductionLoads::clear() {
  blocks_.clear();
  values_.clear();
}

void ConductionLoads::append(Eigen::Index n, const double* C, const double* source) {
  blocks_.push_back({values_.size(), n});
  values_.insert(values_.end(), C, C + n * n);
  values_.insert(values_.end(), source, source + n);
}

void ConductionLoads::keep(const ConductionLoadParts& parts) { append(4, parts.C.data(), parts.source_load.data()); }

void ConductionLoads::keep(const ConductionMatrix& C, const ConductionVector& source) {
  assert(C.rows() == source.size() && C.cols() == source.size());
  append(source.size(), C.data(), source.data());
}

ConductionLoadParts ConductionLoads::report_parts(std::size_t e) const {
  const Block& b = blocks_[e];
  assert(b.n == 4);
  ConductionLoadParts parts;
  parts.C = Eigen::Map<const Eigen::Matrix4d>(values_.data() + b.start);
  parts.source_load = Eigen::Map<const Eigen::Vector4d>(values_.data() + b.start + 16);
  return parts;
}

ConductionMatrix ConductionLoads::capacity(std::size_t e) const {
  const Block& b = blocks_[e];
  return Eigen::Map<const Eigen::MatrixXd>(values_.data() + b.start, b.n, b.n);
}

ConductionVector ConductionLoads::source(std::size_t e) const {
  const Block& b = blocks_[e];
  return Eigen::Map<const Eigen::VectorXd>(values_.data() + b.start + b.n * b.n, b.n);
}

}  // namespace saasgaps
