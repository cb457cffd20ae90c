#pragma once
/// Numbers as people read them on a plot: 12000, 0.0025, 1.25e+06.

#include <string>

namespace saasgaps::plot {

/// Labels for values that are multiples of `step` out to `magnitude` (the largest |value| shown):
/// fixed notation with just enough decimals to tell neighbours apart (step 2.5 -> one decimal),
/// scientific (1.2e+06 style) when magnitude is >= 1e6 or below 1e-3. Zero prints as "0", never "-0".
class TickFormat {
 public:
  TickFormat(double step, double magnitude);
  std::string operator()(double value) const;

 private:
  double step_;
  bool scientific_;
  int decimals_;  ///< after the point, of the fixed number or of the scientific mantissa
};

/// One value on its own, with `significant` digits: fixed notation from 1e-3 to 1e6 (whole numbers keep
/// all their digits: 12519; trailing zeros go: 50, not 50.0), scientific outside.
std::string format_value(double value, int significant = 4);

}  // namespace saasgaps::plot
