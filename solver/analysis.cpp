#include "analysis.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <future>
#include <sstream>

#include "dof_map.hpp"
#include "element_data.hpp"
#include "errors.hpp"
#include "gap_closure.hpp"
#include "material_state.hpp"
#include "sparse_cholesky.hpp"
#include "stiffness_system.hpp"

namespace saasgaps {

const char* to_string(RunStatus status) {
  switch (status) {
    case RunStatus::converged: return "converged";
    case RunStatus::not_converged: return "not_converged";
    case RunStatus::stopped: return "stopped";
  }
  return "?";
}

const char* to_string(GapState state) {
  switch (state) {
    case GapState::open: return "open";
    case GapState::partial: return "partial";
    case GapState::closed: return "closed";
    case GapState::overclosed: return "overclosed";
  }
  return "?";
}

namespace {

/// The model's gap settings with a restart's changes applied.
std::optional<GapSettings> effective_gap_settings(const Model& model, const ResumeOptions& options) {
  if (!model.gaps) return std::nullopt;
  GapSettings s = *model.gaps;
  if (options.tensile_schedule) s.tensile_schedule = *options.tensile_schedule;
  if (options.extrapolation_factor) s.extrapolation_factor = *options.extrapolation_factor;
  return s;
}

/// Everything derived from one iteration's displacements.
struct Evaluation {
  std::vector<ElementState> solids;
  std::vector<ElementState> gaps;
  std::vector<double> gap_strain;
  MaterialUpdate materials;
  GapVerdict gap_verdict;
  bool converged = false;
};

class GapContactAnalysis {
 public:
  GapContactAnalysis(const Model& model, const ResumeOptions& options)
      : model_(model),
        max_iterations_(options.max_iterations.value_or(model.solver.max_iterations)),
        gap_settings_(effective_gap_settings(model, options)),
        dofs_(model),
        materials_(model),
        system_(model, dofs_),
        u_free_(static_cast<std::size_t>(dofs_.size()), 0.0) {
    if (gap_settings_) gaps_.emplace(*gap_settings_);
    schedule_changed_ = options.tensile_schedule.has_value() && options.restart_schedule;
  }

  Solution run(IterationObserver* observer, const RestartState* resume) {
    RestartState state = resume ? resumed(*resume) : fresh();
    Evaluation& eval = eval_;
    if (state.iteration > 0) evaluate(state, eval);

    for (;;) {
      if (state.iteration > 0 && eval.converged) return finish(state, eval, RunStatus::converged);
      if (state.iteration >= max_iterations_) return finish(state, eval, RunStatus::not_converged);
      if (state.iteration > 0 && observer != nullptr && observer->stop_requested()) {
        return finish(state, eval, RunStatus::stopped);
      }
      const auto started = std::chrono::steady_clock::now();

      // Section II (a)-(d): this iteration's gap moduli; strain invariance: its solid moduli.
      const bool first = state.iteration == 0;
      GapModuli moduli = gaps_ ? (first ? gaps_->initial() : gaps_->next(state.gaps)) : GapModuli{};
      // The state's material buffers take the next iteration's values; the evaluation keeps the old
      // ones to overwrite. No per-element allocation from one iteration to the next.
      if (first) {
        state.materials = materials_.initial();
      } else {
        std::swap(state.materials, eval.materials.next);
      }

      solve_linear_system(state.materials, moduli);

      // The snapshot after this iteration: its moduli, its displacements, the previous strains.
      GapHistory history;
      if (!first) {
        history.previous_normal = std::move(state.gaps.used.normal);
        history.previous_strain = std::move(state.gaps.strain);
        history.previous_tensile = state.gaps.used.tensile;
      }
      history.used = std::move(moduli);
      state.gaps = std::move(history);
      state.iteration += 1;
      store_displacements(state.displacement);

      evaluate(state, eval);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      state.history.push_back(record(state, eval, seconds));
      if (observer != nullptr) observer->on_iteration(state.history.back(), state);
    }
  }

 private:
  RestartState fresh() const {
    RestartState s;
    s.node_count = model_.nodes.size();
    s.element_count = model_.elements.size();
    s.gap_count = model_.gap_count();
    return s;
  }

  RestartState resumed(const RestartState& saved) {
    if (saved.version != RestartState::current_version) {
      throw SolverError("restart state version " + std::to_string(saved.version) + " is not supported (expected " +
                        std::to_string(RestartState::current_version) + ")");
    }
    if (saved.node_count != model_.nodes.size() || saved.element_count != model_.elements.size() ||
        saved.gap_count != model_.gap_count() || saved.displacement.size() != 2 * model_.nodes.size() ||
        saved.materials.secant_ratio.size() != model_.elements.size() ||
        saved.materials.compression.size() != model_.elements.size() ||
        saved.gaps.strain.size() != model_.gap_count() || saved.gaps.used.normal.size() != model_.gap_count()) {
      throw SolverError("the restart state does not belong to this model (its dimensions differ)");
    }
    RestartState s = saved;
    s.attempt = saved.attempt + 1;
    if (schedule_changed_ && gaps_) {
      // The READ-card restart: a new schedule starts from its first value at the next iteration.
      s.gaps.used.schedule_step = -1;
    }
    return s;
  }

  /// Assembles what changed and solves K u = f into u_free_.
  void solve_linear_system(const MaterialState& solid, const GapModuli& moduli) {
    // The symbolic analysis needs only the pattern: the first time, it runs on a second core while
    // this one assembles.
    std::future<std::unique_ptr<SparseCholesky>> analysed;
    if (!cholesky_) {
      analysed = std::async(std::launch::async, [this] {
        return std::make_unique<SparseCholesky>(system_.pattern(), dofs_.node_of_equation());
      });
    }
    if (!assembled_solids_ || solid != assembled_materials_) {
      SolidMaterials::LawMemo memo;
      system_.assemble_solids([&](std::size_t e) { return materials_.law(e, solid, memo); });
      assembled_materials_ = solid;
      assembled_solids_ = true;
    }
    if (gaps_) {
      system_.assemble_gaps([&](std::size_t g) { return gaps_->law(g, moduli, model_.analysis); });
    }
    if (analysed.valid()) cholesky_ = analysed.get();
    try {
      cholesky_->factorize(system_.values());
    } catch (const NotPositiveDefinite& e) {
      throw singular_model(e);
    }
    cholesky_->solve(system_.rhs(), u_free_);
    for (double u : u_free_) {
      if (!std::isfinite(u)) throw SolverError("the solution has non-finite displacements");
    }
  }

  SingularModelError singular_model(const NotPositiveDefinite& e) const {
    std::vector<NodeDof> where;
    for (Index column : e.columns()) where.push_back(dofs_.node_dof(column));
    std::ostringstream text;
    text << e.what() << ": the model is not restrained (a free body or an unconnected node) at ";
    const std::size_t shown = std::min<std::size_t>(where.size(), 12);
    for (std::size_t i = 0; i < shown; ++i) {
      text << (i ? ", " : "") << "node " << where[i].node_id << " (" << where[i].direction << ")";
    }
    if (where.size() > shown) text << " and " << where.size() - shown << " more";
    return SingularModelError(text.str(), std::move(where));
  }

  void store_displacements(std::vector<double>& u) const {
    u.assign(2 * model_.nodes.size(), 0.0);
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      for (int dir = 0; dir < 2; ++dir) {
        const Index eq = dofs_.equation(static_cast<int>(n), dir);
        u[2 * n + dir] = eq >= 0 ? u_free_[eq] : dofs_.prescribed(static_cast<int>(n), dir);
      }
    }
  }

  static Vec8 element_displacements(const std::vector<double>& u, const std::array<int, 4>& nodes, int count) {
    Vec8 ue = Vec8::Zero();
    for (int a = 0; a < count; ++a) {
      ue[2 * a] = u[2 * nodes[a]];
      ue[2 * a + 1] = u[2 * nodes[a] + 1];
    }
    return ue;
  }

  /// Recovers stresses and gap strains of iteration K and tests convergence. The same code runs
  /// after a solve and after a resume, which is what makes a restart exact.
  void evaluate(RestartState& state, Evaluation& v) const {
    v.solids.resize(model_.elements.size());
    SolidMaterials::LawMemo memo;
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& el = model_.elements[e];
      const ElementData data = solid_element_data(model_, e, materials_.law(e, state.materials, memo));
      v.solids[e] = element_state(data, element_displacements(state.displacement, el.nodes, el.node_count));
    }
    materials_.update(state.materials, v.solids, model_.solver.plastic_tolerance, v.materials);
    bool converged = v.materials.nonconverged_count == 0 && v.materials.bimodulus_changes == 0;

    if (gaps_) {
      const auto& elements = gap_settings_->elements;
      v.gaps.resize(elements.size());
      v.gap_strain.resize(elements.size());
      for (std::size_t g = 0; g < elements.size(); ++g) {
        const ElementData data = gap_element_data(model_, g, gaps_->law(g, state.gaps.used, model_.analysis));
        v.gaps[g] = element_state(data, element_displacements(state.displacement, elements[g].nodes,
                                                              elements[g].node_count));
        v.gap_strain[g] = normal_component(v.gaps[g].strain, elements[g].angle_deg, 1.0);
      }
      if (state.gaps.strain.empty()) {
        state.gaps.strain = v.gap_strain;  // O(gaps), not O(elements)
      } else {
        // Resuming: the saved strains go on (the same build recomputes them to the last bit). A
        // binary built differently may differ by round-off, and that is still this model's state;
        // anything more means the state belongs to another model.
        for (std::size_t g = 0; g < v.gap_strain.size(); ++g) {
          if (std::abs(v.gap_strain[g] - state.gaps.strain[g]) > 1e-9 * (1.0 + std::abs(state.gaps.strain[g]))) {
            throw SolverError("the restart state does not belong to this model: gap " +
                              std::to_string(elements[g].id) + " has strain " + std::to_string(v.gap_strain[g]) +
                              " here and " + std::to_string(state.gaps.strain[g]) + " in the state");
          }
        }
      }
      v.gap_verdict = gaps_->test(state.gaps);
      converged = converged && v.gap_verdict.all_converged();
    }
    v.converged = converged;
  }

  IterationRecord record(const RestartState& state, const Evaluation& v, double seconds) const {
    IterationRecord row;
    row.iteration = state.iteration;
    row.attempt = state.attempt;
    row.seconds = seconds;
    row.yielded_elements = v.materials.yielded_count;
    row.nonconverged_plastic = v.materials.nonconverged_count;
    row.bimodulus_changes = v.materials.bimodulus_changes;
    if (gaps_) {
      row.tensile_modulus = state.gaps.used.tensile;
      row.extrapolated = state.gaps.used.extrapolated;
      row.closed_gaps = v.gap_verdict.closed;
      row.nonconverged_gaps = v.gap_verdict.nonconverged;
      row.average_closure = v.gap_verdict.average_closure;
      row.max_closure = v.gap_verdict.max_closure;
      row.gap_closures.reserve(v.gap_strain.size());
      for (double eps : v.gap_strain) row.gap_closures.push_back(-100.0 * eps);
    }
    for (int e : model_.output.watch_elements) {
      const Vec4& s = v.solids[e].stress;
      row.watch_elements.push_back({model_.elements[e].id, s[rr], s[zz], s[rz], s[th], von_mises(s)});
    }
    for (int g : model_.output.watch_gaps) {
      const double angle = gap_settings_->elements[g].angle_deg;
      row.watch_gaps.push_back({gap_settings_->elements[g].id, state.gaps.used.normal[g],
                                -100.0 * v.gap_strain[g], normal_component(v.gaps[g].stress, angle, 2.0)});
    }
    return row;
  }

  GapState gap_state(double eps) const {
    const double tolerance = gap_settings_->closure_tolerance;
    if (eps >= 0.0) return GapState::open;
    if (eps <= -1.0 - tolerance) return GapState::overclosed;
    if (eps < -1.0 + tolerance) return GapState::closed;
    return GapState::partial;
  }

  Solution finish(const RestartState& state, const Evaluation& v, RunStatus status) const {
    Solution s;
    s.status = status;
    s.iterations = state.iteration;
    s.history = state.history;
    s.nodes.reserve(model_.nodes.size());
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      const double u_r = state.iteration > 0 ? state.displacement[2 * n] : 0.0;
      const double u_z = state.iteration > 0 ? state.displacement[2 * n + 1] : 0.0;
      s.nodes.push_back({model_.nodes[n].id, u_r, u_z});
    }
    if (state.iteration > 0) {
      for (std::size_t e = 0; e < model_.elements.size(); ++e) {
        const ElementState& es = v.solids[e];
        s.elements.push_back({model_.elements[e].id, es.stress, es.strain, principal_in_plane(es.stress),
                              von_mises(es.stress), v.materials.yielded[e], v.materials.converged[e]});
      }
      for (std::size_t g = 0; g < v.gaps.size(); ++g) {
        const GapElement& gap = gap_settings_->elements[g];
        const double eps = v.gap_strain[g];
        s.gaps.push_back({gap.id, eps, -100.0 * eps, state.gaps.used.normal[g],
                          normal_component(v.gaps[g].stress, gap.angle_deg, 2.0), gap_state(eps),
                          v.gap_verdict.converged[g], v.gap_verdict.failure[g]});
      }
    }
    s.message = message(state, v, status);
    return s;
  }

  std::string message(const RestartState& state, const Evaluation& v, RunStatus status) const {
    std::ostringstream text;
    switch (status) {
      case RunStatus::converged: text << "converged in " << state.iteration << " iterations"; return text.str();
      case RunStatus::stopped: text << "stopped on request after iteration " << state.iteration; break;
      case RunStatus::not_converged:
        text << "not converged after " << state.iteration << " iterations (max_iterations " << max_iterations_ << ")";
        break;
    }
    if (state.iteration == 0) return text.str();
    // Say which gaps and elements still fail, and which test.
    std::vector<std::string> reasons;
    for (std::size_t g = 0; g < v.gap_verdict.failure.size(); ++g) {
      if (v.gap_verdict.failure[g] == GapFailure::none) continue;
      std::ostringstream r;
      r << "gap " << gap_settings_->elements[g].id << " " << describe(v.gap_verdict.failure[g]) << " (closure "
        << -100.0 * v.gap_strain[g] << " %)";
      reasons.push_back(r.str());
    }
    for (std::size_t e = 0; e < v.materials.converged.size(); ++e) {
      if (!v.materials.converged[e]) {
        reasons.push_back("element " + std::to_string(model_.elements[e].id) + " fails N-L/CONV?");
      }
    }
    if (v.materials.bimodulus_changes > 0) {
      reasons.push_back(std::to_string(v.materials.bimodulus_changes) +
                        " elements switched tension/compression properties");
    }
    if (!reasons.empty()) {
      text << ": ";
      const std::size_t shown = std::min<std::size_t>(reasons.size(), 10);
      for (std::size_t i = 0; i < shown; ++i) text << (i ? "; " : "") << reasons[i];
      if (reasons.size() > shown) text << "; and " << reasons.size() - shown << " more";
    }
    return text.str();
  }

  const Model& model_;
  int max_iterations_;
  std::optional<GapSettings> gap_settings_;
  std::optional<GapClosure> gaps_;
  bool schedule_changed_ = false;
  DofMap dofs_;
  SolidMaterials materials_;
  StiffnessSystem system_;
  std::unique_ptr<SparseCholesky> cholesky_;  // symbolic analysis once, at the first solve
  Evaluation eval_;                           // per-element buffers, reused every iteration
  MaterialState assembled_materials_;
  bool assembled_solids_ = false;
  std::vector<double> u_free_;
};

}  // namespace

Solution solve(const Model& model, IterationObserver* observer, const RestartState* resume,
               const ResumeOptions& options) {
  GapContactAnalysis analysis(model, options);
  return analysis.run(observer, resume);
}

}  // namespace saasgaps
