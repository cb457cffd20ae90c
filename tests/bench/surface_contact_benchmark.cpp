// saasgaps_surface_contact_bench: contact surfaces (model.contact, mortar rows solved by the exact
// mode's active-set solver) against one numeric factorization + solve of the same matrix, measured in
// the same run.
//
//   build/tests/bench/saasgaps_surface_contact_bench --dofs 1.5e5
//   build/tests/bench/saasgaps_surface_contact_bench --dofs 1.5e5 --eccentric 2
//   build/tests/bench/saasgaps_surface_contact_bench --dofs 1e6 --repeat 1
//   build/tests/bench/saasgaps_surface_contact_bench --quad8 --dofs 1.5e5 [--eccentric 2]
//
// --quad8: the same fit as a quarter of both rings of quad8 elements, mid-side nodes on the circles
// (shrink_fit_rings.hpp's quarter_shrink_fit: 5 shaft edges to 4 of the hub's, as the issue's
// 20 against 16), curved 3-node contact surfaces; --eccentric e there widens the bore from 0 at 0
// degrees to e interferences at 90 (e > 1: the fit opens towards 90 degrees).
//
// The model is the plane-strain shrink fit of tests/verification/surface_contact_test.cpp at scale
// (tests/support/shrink_fit_rings.hpp): two whole rings (1..1.5 and 1.5..2.2, E 30e6 and 10e6) meshed on their own with non-matching
// interfaces (`around` segments on the shaft, 5/3 of that on the bore), an interference of 1e-4 of
// the radius, each ring held against rigid motion at three nodes. Every row ends in contact (the
// first active set is every row, since every initial gap is < 0). Reported: building the rows (pairing
// and integration), the baseline (one numeric factorization of K, whose pattern holds the rows'
// couplings, and one solve), the contact solve from a cold start, and the ratios.
//
// --eccentric e moves the shaft by e interferences along +r: the initial gap round the interface is
// then about -delta (1 + e cos theta), so for e > 1 the points where cos theta < -1/e start open and
// the contact must find where it ends (a partial contact: several active sets).
//
// Unless --around is given, the mesh keeps the shape of its elements at every size: `around` grows
// with the square root of the unknowns (600 at 10^5, 732 at 1.5 x 10^5, 1896 at 10^6; a multiple of
// 12, so that both rings' counts are multiples of 4).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/contact/exact_contact.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/mortar/mortar_method.hpp"
#include "support/shrink_fit_rings.hpp"

#include "peak_memory.hpp"
#include "stopwatch.hpp"

using namespace saasgaps;

namespace {

using saasgaps::bench::peak_rss_mib;
using saasgaps::bench::timed;

/// Moves the nodes of the shaft (the elements of material 0) by `offset` along r.
void move_shaft(Model& m, double offset) {
  std::vector<bool> shaft(m.nodes.size(), false);
  for (const Element& e : m.elements) {
    if (e.material != 0) continue;
    for (int k = 0; k < e.node_count; ++k) shaft[static_cast<std::size_t>(e.nodes[k])] = true;
  }
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    if (shaft[n]) m.nodes[n].r += offset;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times the contact-surface solve against one factorization + solve of the same matrix"};
  double target_dofs = 1.0e5;
  int around = 0;
  int repeat = 3;
  double eccentric = 0.0;
  bool quad8 = false;
  app.add_option("--dofs", target_dofs, "Approximate number of degrees of freedom (at most 2e6)")
      ->check(CLI::Range(100.0, 2.0e6));
  app.add_option("--around", around, "Segments round the shaft, a multiple of 12 (the bore has 5/3 as many); "
                 "default: 600 sqrt(dofs / 1e5)")->check(CLI::Range(12, 100000));
  app.add_option("--eccentric", eccentric,
                 "Move the shaft by this many interferences along r: above 1, part of the interface opens")
      ->check(CLI::Range(0.0, 100.0));
  app.add_flag("--quad8", quad8, "Quarter rings of quad8 with curved 3-node contact surfaces");
  app.add_option("--repeat", repeat, "Runs of each timing; the best is reported")->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);
  if (around == 0) around = 12 * std::max(1, static_cast<int>(std::lround(50.0 * std::sqrt(target_dofs / 1.0e5))));
  if (around % 12 != 0) {
    std::fprintf(stderr, "--around must be a multiple of 12 (both rings' counts multiples of 4)\n");
    return 1;
  }

  // (radial + 1) x (around + 5/3 around) nodes, 2 unknowns each; quad8: about 3 radial x around
  // nodes per quarter ring (around / 4 edges on the shaft's quarter, 4/5 of that on the hub's).
  const int total_around = around + around * 5 / 3;
  int radial = std::max(1, static_cast<int>(std::lround(target_dofs / (2.0 * total_around))) - 1);
  Model m;
  std::array<int, 2> faces{around, around * 5 / 3};
  if (quad8) {
    faces = {around / 4, around / 4 * 4 / 5};
    radial = std::max(1, static_cast<int>(std::lround(target_dofs / (6.0 * (faces[0] + faces[1])))));
    m = testing::shrink_fit_rings::quarter_shrink_fit(radial, faces, eccentric);
  } else {
    m = testing::shrink_fit_rings::shrink_fit(AnalysisType::plane_strain, radial, faces);
    move_shaft(m, eccentric * testing::shrink_fit_rings::delta);
  }
  SurfaceContact surfaces;
  double rows_s = 1e300;
  for (int r = 0; r < repeat; ++r) rows_s = std::min(rows_s, timed([&] { surfaces = surface_contact(m); }));
  // The pairing's search against the all-against-all loop it replaced (rows of the one pair).
  const SurfaceMeasure measure{m.analysis, m.thickness};
  double search_s = 1e300, all_s = 1e300;
  for (int r = 0; r < repeat; ++r) {
    search_s = std::min(search_s, timed([&] {
      (void)mortar_rows(m.nodes, measure, surfaces.surfaces[0], surfaces.surfaces[1], Pairing::search);
    }));
    all_s = std::min(all_s, timed([&] {
      (void)mortar_rows(m.nodes, measure, surfaces.surfaces[0], surfaces.surfaces[1], Pairing::all_against_all);
    }));
  }
  DofMap dofs(m);
  StiffnessSystem system(m, dofs, contact_couplings(surfaces, dofs));
  const SolidMaterials materials(m);
  const MaterialState state = materials.initial();
  system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
  SparseCholesky cholesky(system.pattern(), dofs.node_of_equation());
  std::vector<double> u(static_cast<std::size_t>(dofs.size()));

  // The best of `repeat` runs of each, interleaved, so that a busy machine disturbs both alike.
  cholesky.factorize(system.values());  // first touch of the factor's memory, not timed
  ExactContact contact(m, dofs, system.pattern(), surfaces.pairs);
  ContactReport report;
  double factorize_s = 1e300, solve_s = 1e300, contact_s = 1e300;
  for (int r = 0; r < repeat; ++r) {
    factorize_s = std::min(factorize_s, timed([&] { cholesky.factorize(system.values()); }));
    solve_s = std::min(solve_s, timed([&] { cholesky.solve(system.rhs(), u); }));
    ContactState cold;
    contact_s = std::min(contact_s, timed([&] { report = contact.solve(cholesky, system.values(), system.rhs(), cold, u); }));
  }
  const double baseline = factorize_s + solve_s;
  std::printf("model: plane-strain shrink fit, %d x (%d, %d) %s, %lld unknowns, %zu contact rows, nnz(L) %.3g, "
              "%.3g Gflop per factorization, %s by %g interferences\n",
              radial, faces[0], faces[1], quad8 ? "quad8 (quarter rings)" : "quads", static_cast<long long>(dofs.size()),
              surfaces.pairs.pairs.size(),
              cholesky.factor_nonzeros(), cholesky.factor_flops() / 1e9, quad8 ? "bore widened" : "shaft moved", eccentric);
  std::printf("%-52s %10.3f\n", "contact rows (pairing and integration)", rows_s);
  std::printf("%-52s %10.3f\n", "  of which mortar rows, bin search", search_s);
  std::printf("%-52s %10.3f\n", "  the same rows, all against all", all_s);
  std::printf("%-52s %10.3f\n", "numeric factorization", factorize_s);
  std::printf("%-52s %10.3f\n", "solve", solve_s);
  std::printf("%-52s %10.3f\n", "contact solve (cold start)", contact_s);
  std::printf("  active sets %d (factorizations %d, the others solved on a factorization held: corrected or updated), multiplier solves %d, rows in contact %d, "
              "complementarity %.2e\n",
              report.active_set_iterations, report.factorizations, report.multiplier_iterations, report.pairs_in_contact,
              report.complementarity);
  std::printf("ratio contact solve / (factorization + solve): %.3f\n", contact_s / baseline);
  std::printf("ratio (rows + contact solve) / (factorization + solve): %.3f\n", (rows_s + contact_s) / baseline);
  std::printf("peak RSS of the process: %.0f MiB\n", peak_rss_mib());
  return 0;
}
