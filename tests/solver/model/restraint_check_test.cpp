// The restraint check against what it decides: the rigid-body modes each analysis allows, bodies
// joined through gaps or contact pairs, nodes no element uses.
#include <gtest/gtest.h>

#include "solver/model/restraint_check.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

using testing::add_gap_row;
using testing::add_grid;
using testing::constrain;

/// Two 2 x 2 blocks, the upper one 0.1 above the lower; gap elements join them when asked.
struct TwoBlocks {
  Model model;
  testing::Grid lower, upper;
  explicit TwoBlocks(AnalysisType type, bool gaps) {
    model.analysis = type;
    model.materials.push_back(testing::isotropic_material(1, 1.0e7, 0.3));
    lower = add_grid(model, 2, 2, [](double s, double t) { return Vec2{1.0 + s, t}; }, 0);
    upper = add_grid(model, 2, 2, [](double s, double t) { return Vec2{1.0 + s, 1.1 + t}; }, 0);
    if (gaps) {
      model.gaps.emplace();
      add_gap_row(model, {lower.at(0, 2), lower.at(1, 2), lower.at(2, 2)}, {upper.at(0, 0), upper.at(1, 0), upper.at(2, 0)},
                  [](int) { return 90.0; });
    }
  }
};

TEST(RestraintCheck, PlaneBodyNeedsBothTranslationsAndTheRotation) {
  TwoBlocks b(AnalysisType::plane_strain, true);
  constrain(b.model, b.lower.at(0, 0), 0.0, 0.0);
  // Pinned at one node: free to rotate about it.
  auto issues = check_restraint(b.model);
  ASSERT_EQ(issues.size(), 1U);
  EXPECT_EQ(issues[0].kind, RestraintIssue::Kind::unrestrained_body);
  EXPECT_EQ(issues[0].nodes.size(), 18U);  // both blocks: the gaps join them
  ASSERT_EQ(issues[0].motions.size(), 1U);
  EXPECT_STREQ(issues[0].motions[0], "rotation");
  // A roller beside the pin stops the rotation: r fixed at a node at another height.
  constrain(b.model, b.lower.at(0, 1), 0.0, std::nullopt);
  EXPECT_TRUE(check_restraint(b.model).empty());
}

TEST(RestraintCheck, RollersAlongOneLineLeaveTheTranslationAlongIt) {
  TwoBlocks b(AnalysisType::plane_stress, true);
  for (int i = 0; i <= 2; ++i) constrain(b.model, b.lower.at(i, 0), std::nullopt, 0.0);
  const auto issues = check_restraint(b.model);
  ASSERT_EQ(issues.size(), 1U);
  ASSERT_EQ(issues[0].motions.size(), 1U);
  EXPECT_STREQ(issues[0].motions[0], "translation r");
}

TEST(RestraintCheck, BodiesWithoutGapsAreCheckedOneByOne) {
  TwoBlocks b(AnalysisType::plane_strain, false);
  constrain(b.model, b.lower.at(0, 0), 0.0, 0.0);
  constrain(b.model, b.lower.at(2, 0), std::nullopt, 0.0);
  const auto issues = check_restraint(b.model);
  ASSERT_EQ(issues.size(), 1U);  // the upper block floats
  EXPECT_EQ(issues[0].nodes.front(), b.upper.at(0, 0));
  EXPECT_EQ(issues[0].motions.size(), 3U);
}

TEST(RestraintCheck, AContactPairJoinsItsSurfacesBodiesLikeAClosedGap) {
  // An axisymmetric body held only by being pressed onto another through contact surfaces.
  TwoBlocks b(AnalysisType::axisymmetric, false);
  constrain(b.model, b.lower.at(0, 0), std::nullopt, 0.0);
  ASSERT_EQ(check_restraint(b.model).size(), 1U);  // the upper block is free in z
  ContactSettings& contact = b.model.contact.emplace();
  contact.surfaces = {{"lower", {{b.lower.at(0, 2), b.lower.at(1, 2)}}}, {"upper", {{b.upper.at(1, 0), b.upper.at(0, 0)}}}};
  contact.pairs.emplace_back().surfaces = {0, 1};
  EXPECT_TRUE(check_restraint(b.model).empty());
}

TEST(RestraintCheck, AxisymmetricBodyNeedsOnlyAnAxialConstraint) {
  TwoBlocks b(AnalysisType::axisymmetric, true);
  // A radial constraint alone holds nothing the hoop strain does not already hold.
  constrain(b.model, b.lower.at(0, 0), 0.0, std::nullopt);
  auto issues = check_restraint(b.model);
  ASSERT_EQ(issues.size(), 1U);
  ASSERT_EQ(issues[0].motions.size(), 1U);
  EXPECT_STREQ(issues[0].motions[0], "translation z");
  constrain(b.model, b.upper.at(1, 2), std::nullopt, 0.0);  // held through the gaps
  EXPECT_TRUE(check_restraint(b.model).empty());
}

TEST(RestraintCheck, NodeNoElementUsesMustBeFullyPrescribed) {
  TwoBlocks b(AnalysisType::plane_strain, true);
  constrain(b.model, b.lower.at(0, 0), 0.0, 0.0);
  constrain(b.model, b.lower.at(2, 0), 0.0, 0.0);
  b.model.nodes.push_back({9999, 5.0, 5.0});
  b.model.loads.node_temperature.push_back(0.0);
  auto issues = check_restraint(b.model);
  ASSERT_EQ(issues.size(), 1U);
  EXPECT_EQ(issues[0].kind, RestraintIssue::Kind::orphan_node);
  EXPECT_EQ(issues[0].nodes.front(), static_cast<int>(b.model.nodes.size()) - 1);
  constrain(b.model, static_cast<int>(b.model.nodes.size()) - 1, 0.0, 0.0);
  EXPECT_TRUE(check_restraint(b.model).empty());
}

}  // namespace
}  // namespace saasgaps
