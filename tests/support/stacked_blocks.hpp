#pragma once
/// Two blocks stacked along z with non-matching meshes on their facing faces: the geometry of the
/// contact patch test (tests/verification/mortar_patch_test.cpp) and of the mortar unit tests.

#include <array>
#include <vector>

#include "solver/model/model.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps::testing {

/// One block's face: the r positions of its nodes are r0 + width s^grading, s = i / segments.
struct BlockFace {
  int segments = 5;
  double grading = 1.0;
};

struct StackedBlocks {
  Model model;
  Grid lower;  ///< [r0, r0 + width] x [0, height], material 0
  Grid upper;  ///< [r0, r0 + width] x [height + gap, 2 height + gap], material 1
  std::vector<std::array<int, 2>> lower_top;     ///< the lower block's top face, left to right
  std::vector<std::array<int, 2>> upper_bottom;  ///< the upper block's bottom face, left to right
};

/// gap < 0 makes the blocks overlap (an interference). Materials: E 1e6, nu 0.3 below; E 3e6,
/// nu 0.2 above. Temperatures filled at 0.
StackedBlocks stacked_blocks(AnalysisType analysis, double r0, double width, double height, double gap,
                             BlockFace lower, BlockFace upper, int layers);

/// The patch test's cases (mortar_patch_test, surface_contact_test): non-matching faces of 5 graded
/// segments (lower block) against 7 (upper), each analysis, either face as side A, touching (gap 0)
/// or overlapping (an interference).
struct PatchCase {
  const char* name;
  AnalysisType analysis;
  bool lower_is_a;
  double gap;
};

inline const std::vector<PatchCase>& patch_cases() {
  static const std::vector<PatchCase> cases = {
      {"plane stress, 5 on 7", AnalysisType::plane_stress, true, 0.0},
      {"plane stress, 7 on 5", AnalysisType::plane_stress, false, 0.0},
      {"plane strain, 5 on 7", AnalysisType::plane_strain, true, 0.0},
      {"plane strain, 7 on 5, interference", AnalysisType::plane_strain, false, -0.01},
      {"axisymmetric, 5 on 7", AnalysisType::axisymmetric, true, 0.0},
      {"axisymmetric, 7 on 5", AnalysisType::axisymmetric, false, 0.0},
      {"axisymmetric, 5 on 7, interference", AnalysisType::axisymmetric, true, -0.01},
  };
  return cases;
}

/// The edges of grid row j (nodes (i, j) - (i + 1, j)), i = 0..ni-1.
std::vector<std::array<int, 2>> row_edges(const Grid& grid, int j);

/// The edges of grid column i (nodes (i, j) - (i, j + 1)), j = 0..nj-1.
std::vector<std::array<int, 2>> column_edges(const Grid& grid, int i);

/// Adds the consistent nodal loads (fe/edge_loads.hpp's edge_traction_loads) of a uniform traction
/// (force per unit area, along r and z) on the given edges, as nodal forces.
void add_traction(Model& model, const std::vector<std::array<int, 2>>& edges, const Vec2& traction);

}  // namespace saasgaps::testing
