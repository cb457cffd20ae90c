#pragma once
/// The load parts of every solid element of one conduction assembly, kept so that a later time step
/// whose matrix is unchanged assembles its right-hand side with no element kernel
/// (ThermalSystem::assemble_rhs). Per element, whatever its family, the two things its rhs is made
/// of besides the step's own values (previous temperatures, c / dt, the source):
///   C    the capacity matrix, n x n (column-major), and
///   s    the source part, n,
/// n the unknowns of the kernel's block: the report's elements (conduction_kernel.hpp) 4, a triangle
/// zero-padded, C their corner capacity and s their source load (times the power density); the
/// other families (isoparametric_conduction.hpp) their node count, C = sum N N^T dV and s = sum N dV.
/// Each kernel forms f from its parts with the function its whole block uses (conduction_load,
/// isoparametric_conduction_load), so the rhs has the whole assembly's bits.
///
/// Memory: n (n + 1) doubles an element (20 for the report's, 72 for quad8, 90 for quad9), one block
/// after the other in element order.

#include <cstddef>
#include <span>
#include <vector>

#include "solver/thermal/conduction_kernel.hpp"
#include "solver/thermal/isoparametric_conduction.hpp"

namespace saasgaps {

class ConductionLoads {
 public:
  /// Forgets every element's parts: the next keep is element 0's.
  void clear();
  /// Keeps the next element's parts (elements in order 0, 1, ...).
  void keep(const ConductionLoadParts& parts);
  void keep(const ConductionMatrix& C, const ConductionVector& source);

  /// Elements kept.
  [[nodiscard]] std::size_t size() const { return blocks_.size(); }
  [[nodiscard]] bool empty() const { return blocks_.empty(); }

  /// Element e's parts, as kept by the first keep (the report's elements).
  [[nodiscard]] ConductionLoadParts report_parts(std::size_t e) const;
  /// Element e's C and s, as kept by the second keep (the other families).
  [[nodiscard]] ConductionMatrix capacity(std::size_t e) const;
  [[nodiscard]] ConductionVector source(std::size_t e) const;

 private:
  struct Block {
    std::size_t start = 0;  ///< its first value in values_
    Eigen::Index n = 0;     ///< its unknowns: n (n + 1) values
  };
  void append(Eigen::Index n, const double* C, const double* source);

  std::vector<Block> blocks_;   // per element
  std::vector<double> values_;  // per element C (column-major) then s
};

}  // namespace saasgaps
