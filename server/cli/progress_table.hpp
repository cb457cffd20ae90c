#pragma once
/// The iteration table on stderr, with the columns of the report's Tables I-V: tensile modulus,
/// closed gaps, non-converged gaps, average and maximum closure, yielded and non-converged plastic
/// elements, then the watched elements and gaps.

#include <ostream>
#include <string>

#include "iteration_record.hpp"

namespace saasgaps::cli {

class ProgressTable {
 public:
  explicit ProgressTable(std::ostream& out) : out_(out) {}
  void print(const IterationRecord& row);

 private:
  void print_header(const IterationRecord& row);
  std::ostream& out_;
  bool header_done_ = false;
  bool exact_ = false;  // the rows carry exact-contact columns
};

}  // namespace saasgaps::cli
