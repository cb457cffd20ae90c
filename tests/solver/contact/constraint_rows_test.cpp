// Where a cold contact solve starts (contact_start, solver/constraint_rows.hpp).

#include <gtest/gtest.h>

#include <vector>

#include "solver/contact/constraint_rows.hpp"

namespace saasgaps {
namespace {

TEST(ContactStart, WithoutInterferenceTheRowsWithinOnePercentOfTheSmallestGap) {
  const std::vector<double> g0{0.5, 0.504, 0.506, 2.0};
  EXPECT_DOUBLE_EQ(contact_start(g0), 0.505);
  const std::vector<double> touching{0.0, 0.0, 1.0};
  EXPECT_EQ(contact_start(touching), 0.0);  // closed rows only
}

TEST(ContactStart, WithAnInterferenceEveryRowWithinTheLargestInterference) {
  // An eccentric fit: gaps -delta (1 + 2 cos theta) from -3 delta to +delta; the parts deform by
  // about 3 delta, so every row starts active, the open ones included.
  const std::vector<double> eccentric{-3.0e-3, -1.0e-3, 0.0, 0.5e-3, 1.0e-3};
  EXPECT_DOUBLE_EQ(contact_start(eccentric), 3.0e-3);
  // A small interference beside wide gaps: the wide ones stay open at first.
  const std::vector<double> mixed{-1.0e-4, 2.0e-4, 5.0e-3};
  EXPECT_DOUBLE_EQ(contact_start(mixed), 1.0e-4);
}

}  // namespace
}  // namespace saasgaps
