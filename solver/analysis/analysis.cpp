#include "solver/analysis/analysis.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <future>
#include <sstream>

#include "solver/analysis/reactions.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/base/errors.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/base/plural.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/model/load_schedule.hpp"
#include "solver/mortar/mortar_method.hpp"
#include "solver/recovery/stress_recovery.hpp"

namespace saasgaps {

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
  std::vector<ElementState> points;   ///< per material point (fe/material_points.hpp)
  std::vector<ElementState> centres;  ///< per solid element: the state elements[] reports
  MaterialUpdate materials;
  ContactOutcome contact;
  bool converged = false;  ///< the materials' verdict AND the contact method's
};

/// Everything one increment's loads and constraints determine: the numbering (prescribed
/// components), the solid laws (temperatures), K and f, the contact method built on them, and the
/// factorization. A model without steps has one, built on the model itself.
struct IncrementSystem {
  IncrementSystem(const Model& solved, const GapSettings* gaps, const SurfaceContact& surfaces,
                  const ContactMethodFactory& make_contact)
      : model(solved),
        dofs(solved),
        materials(solved),
        system(solved, dofs, contact_couplings(surfaces, dofs)),
        contact(make_contact({solved, gaps, dofs, system.pattern(), &surfaces})),
        u_free(static_cast<std::size_t>(dofs.size()), 0.0) {}

  const Model& model;  // the model itself, or the increment's (LoadSchedule::increment_model)
  DofMap dofs;
  SolidMaterials materials;
  StiffnessSystem system;
  std::unique_ptr<ContactMethod> contact;
  std::future<std::unique_ptr<SparseCholesky>> analysed;  // the symbolic analysis under way
  std::unique_ptr<SparseCholesky> cholesky;               // symbolic analysis once, at the first solve
  /// Stepped runs: the pattern `cholesky` analysed, owned apart from `system` (the factorization
  /// refers to it), so that the analysis passes on to the next increment when its numbering is the
  /// same. Null without steps: the analysis is of system.pattern().
  std::unique_ptr<CscPattern> analysed_pattern;
  MaterialState assembled_materials;
  bool assembled_solids = false;
  std::vector<double> u_free;
};

class GapContactAnalysis {
 public:
  GapContactAnalysis(const Model& model, const ResumeOptions& options, const OrderingCache* cache,
                     const ContactMethodFactory& make_contact)
      : model_(model),
        ordering_cache_(cache),
        max_iterations_(options.max_iterations.value_or(model.solver.max_iterations)),
        gap_settings_(effective_gap_settings(model, options)),
        surfaces_(surface_contact(model)),
        make_contact_(make_contact),
        schedule_(model),
        material_points_(MaterialPoints(model).size()) {
    schedule_changed_ = options.tensile_schedule.has_value() && options.restart_schedule;
  }

  /// Per increment (a model without steps has one): the bounded contact and material iteration
  /// until both verdicts hold; then the next increment starts from this one's state.
  Solution run(IterationObserver* observer, const RestartState* resume) {
    RestartState state = resume ? resumed(*resume) : fresh();
    begin_increment(state);
    // A saved state is written after a solve, so it was solved in the increment it names.
    solved_in_increment_ = state.iteration > 0;
    Evaluation& eval = eval_;
    if (state.iteration > 0) evaluate(state, eval);

    for (;;) {
      if (increment_iterations(state) > 0 && eval.converged) {
        if (!next_increment(state)) return finish(state, eval, RunStatus::converged);
      }
      if (increment_iterations(state) >= max_iterations_) return finish(state, eval, RunStatus::not_converged);
      if (state.iteration > 0 && observer != nullptr && observer->stop_requested()) {
        return finish(state, eval, RunStatus::stopped);
      }
      const auto started = std::chrono::steady_clock::now();

      // Strain invariance: this iteration's solid moduli. The state's material buffers take the next
      // iteration's values; the evaluation keeps the old ones to overwrite. No per-element allocation
      // from one iteration to the next.
      if (state.iteration == 0) {
        state.materials = now_->materials.initial();
      } else {
        std::swap(state.materials, eval.materials.next);
      }
      // K and f: the solids, then what the contact method adds (section II (a)-(d): the gap moduli).
      assemble(state);
      solve_linear_system(state);
      state.iteration += 1;
      if (state.position) state.position->iterations += 1;
      store_displacements(state.displacement);
      solved_in_increment_ = true;

      evaluate(state, eval);
      now_->contact->check_solved(state, eval.contact);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      state.history.push_back(record(state, eval, seconds));
      if (observer != nullptr) observer->on_iteration(state.history.back(), state);
    }
  }

 private:
  /// Iterations of the current increment (a model without steps: of the run).
  static int increment_iterations(const RestartState& state) {
    return state.position ? state.position->iterations : state.iteration;
  }

  /// Builds the system of the state's increment: the model itself without steps.
  void begin_increment(const RestartState& state) {
    const GapSettings* gaps = gap_settings_ ? &*gap_settings_ : nullptr;
    if (!state.position) {
      now_ = std::make_unique<IncrementSystem>(model_, gaps, surfaces_, make_contact_);
      return;
    }
    // The last increment's system is only read below (its numbering and analysis), while the model
    // it was built on takes the new increment's values.
    increment_model_ = schedule_.increment_model(*state.position);
    auto next = std::make_unique<IncrementSystem>(increment_model_, gaps, surfaces_, make_contact_);
    if (now_ && now_->cholesky && same_numbering(now_->dofs, next->dofs)) {
      // Same prescribed components, so the same pattern: its symbolic analysis holds.
      next->analysed_pattern = std::move(now_->analysed_pattern);
      next->cholesky = std::move(now_->cholesky);
    } else {
      next->analysed_pattern = std::make_unique<CscPattern>(next->system.pattern());
    }
    now_ = std::move(next);
  }

  bool same_numbering(const DofMap& a, const DofMap& b) const {
    if (a.size() != b.size()) return false;
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      for (int dir = 0; dir < 2; ++dir) {
        if (a.equation(static_cast<int>(n), dir) != b.equation(static_cast<int>(n), dir)) return false;
      }
    }
    return true;
  }

  /// After a converged increment: the next one, carrying the materials', contact and gap history of
  /// this one in the state. False after the last.
  bool next_increment(RestartState& state) {
    if (!state.position) return false;
    // The peaks of this increment's yielded elements go into the state the next one starts from.
    if (now_->materials.nonlinear()) now_->materials.record_peaks(state.materials, eval_.points, eval_.materials.next);
    if (!schedule_.advance(*state.position, state.displacement)) return false;
    begin_increment(state);
    solved_in_increment_ = false;
    return true;
  }

  RestartState fresh() const {
    RestartState s;
    s.version = restart_version(model_);
    if (schedule_.stepped()) s.position = schedule_.first();
    s.node_count = model_.nodes.size();
    s.element_count = model_.elements.size();
    s.material_point_count = material_points_;
    s.gap_count = model_.gap_count();
    return s;
  }

  RestartState resumed(const RestartState& saved) {
    const int expected = restart_version(model_);
    // A plastic stepped model's state from before peaks were kept (version 2) reads as one without.
    const bool before_peaks =
        expected == RestartState::plastic_steps_version && saved.version == RestartState::stepped_version;
    if (saved.version != expected && !before_peaks) {
      throw SolverError("restart state version " + std::to_string(saved.version) + " is not supported (expected " +
                        std::to_string(expected) + (schedule_.stepped() ? " for a model with steps)" : ")"));
    }
    if (saved.position.has_value() != schedule_.stepped() ||
        (saved.position && !schedule_.holds(*saved.position, model_.nodes.size()))) {
      throw SolverError("the restart state does not belong to this model (its load steps differ)");
    }
    const std::size_t points = material_points_;
    if (saved.node_count != model_.nodes.size() || saved.element_count != model_.elements.size() ||
        saved.material_point_count != points || saved.gap_count != model_.gap_count() ||
        saved.displacement.size() != 2 * model_.nodes.size() || saved.materials.secant_ratio.size() != points ||
        saved.materials.compression.size() != points ||
        saved.gaps.strain.size() != model_.gap_count() || saved.gaps.used.normal.size() != model_.gap_count()) {
      throw SolverError("the restart state does not belong to this model (its dimensions differ)");
    }
    check_plastic_branches(saved.materials);
    RestartState s = saved;
    s.version = expected;
    s.attempt = saved.attempt + 1;
    // The READ-card restart: a new schedule starts from its first value at the next iteration (-1 is
    // also what a model without gaps keeps there).
    if (schedule_changed_) s.gaps.used.schedule_step = -1;
    return s;
  }

  /// Peaks and unloading branches of a saved state: none, or one per material point; a point unloads
  /// only from a peak it reached, and only in a plastic stepped model.
  void check_plastic_branches(const MaterialState& m) const {
    const std::size_t n = material_points_;
    const bool kept = restart_version(model_) == RestartState::plastic_steps_version;
    const auto fits = [&](std::size_t size) { return size == 0 || (kept && size == n); };
    if (!fits(m.peaks.size()) || !fits(m.unloading.size())) {
      throw SolverError("the restart state does not belong to this model (its plastic peaks differ)");
    }
    for (std::size_t e = 0; e < m.unloading.size(); ++e) {
      if (m.unloads(e) && (m.peaks.empty() || !m.peaks[e].reached())) {
        throw SolverError("the restart state does not belong to this model (material point " + std::to_string(e) +
                          " unloads from no peak)");
      }
    }
  }

  /// K and f of the next iteration: the solids when their moduli changed, then the contact method's
  /// part. The symbolic analysis needs only the pattern: the first time, it runs on a second core
  /// while this one assembles.
  void assemble(RestartState& state) {
    IncrementSystem& now = *now_;
    if (!now.cholesky) {
      now.analysed = std::async(std::launch::async, [this, &now] {
        const CscPattern& pattern = now.analysed_pattern ? *now.analysed_pattern : now.system.pattern();
        return std::make_unique<SparseCholesky>(pattern, now.dofs.node_of_equation(), ordering_cache_);
      });
    }
    if (!now.assembled_solids || state.materials != now.assembled_materials) {
      SolidMaterials::LawMemo memo;
      now.system.assemble_solids([&](std::size_t e, std::span<Constitutive> scratch) {
        return now.materials.laws(e, state.materials, memo, scratch);
      });
      now.assembled_materials = state.materials;
      now.assembled_solids = true;
    }
    now.contact->begin_iteration(state, now.system);
    if (now.analysed.valid()) now.cholesky = now.analysed.get();
  }

  /// K u = f into the increment's u_free, contact enforced by the method.
  void solve_linear_system(RestartState& state) {
    IncrementSystem& now = *now_;
    try {
      now.contact->solve(*now.cholesky, now.system.values(), now.system.rhs(), state, now.u_free);
    } catch (const NotPositiveDefinite& e) {
      throw singular_model(e);
    }
    for (double u : now.u_free) {
      if (!std::isfinite(u)) throw SolverError("the solution has non-finite displacements");
    }
  }

  SingularModelError singular_model(const NotPositiveDefinite& e) const {
    std::vector<NodeDof> where;
    for (Index column : e.columns()) where.push_back(now_->dofs.node_dof(column));
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
    const IncrementSystem& now = *now_;
    u.resize(2 * model_.nodes.size());  // every entry is written below
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      for (int dir = 0; dir < 2; ++dir) {
        const Index eq = now.dofs.equation(static_cast<int>(n), dir);
        u[2 * n + dir] = eq >= 0 ? now.u_free[eq] : now.dofs.prescribed(static_cast<int>(n), dir);
      }
    }
  }

  /// Recovers stresses of iteration K and the contact method's measurements, and judges convergence.
  /// The same code runs after a solve and after a resume, which is what makes a restart exact.
  void evaluate(RestartState& state, Evaluation& v) const {
    const IncrementSystem& now = *now_;
    const MaterialPoints& points = now.materials.points();
    v.points.resize(points.size());
    v.centres.resize(model_.elements.size());
    SolidMaterials::LawMemo memo;
    std::array<Constitutive, max_material_points> laws;
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& el = model_.elements[e];
      const ElementData data = solid_element_data(now.model, e, now.materials.laws(e, state.materials, memo, laws));
      const ElementStates s = element_states(data, values(element_displacements(state.displacement, el.node_span())));
      std::copy_n(s.point.begin(), s.point_count, v.points.begin() + static_cast<std::ptrdiff_t>(points.first(e)));
      v.centres[e] = s.centre;
    }
    now.materials.update(state.materials, v.points, model_.solver.plastic_tolerance, v.materials);
    const bool materials_converged = v.materials.nonconverged_count == 0 && v.materials.bimodulus_changes == 0;
    now.contact->evaluate(state, v.contact);
    v.converged = materials_converged && v.contact.converged();
  }

  IterationRecord record(const RestartState& state, const Evaluation& v, double seconds) const {
    IterationRecord row;
    row.iteration = state.iteration;
    if (state.position) {
      row.step = state.position->step + 1;
      row.increment = state.position->increment;
    }
    row.attempt = state.attempt;
    row.seconds = seconds;
    row.yielded_elements = v.materials.yielded_count;
    row.nonconverged_plastic = v.materials.nonconverged_count;
    row.bimodulus_changes = v.materials.bimodulus_changes;
    const ContactOutcome& c = v.contact;
    row.closed_gaps = c.closed;
    row.nonconverged_gaps = c.nonconverged;
    row.average_closure = c.average_closure;
    row.max_closure = c.max_closure;
    row.gap_closures.reserve(c.gaps.size());
    for (const GapResult& g : c.gaps) row.gap_closures.push_back(g.closure);
    now_->contact->add_columns(state, row);
    for (int e : model_.output.watch_elements) {
      const Vec4& s = v.centres[static_cast<std::size_t>(e)].stress;
      row.watch_elements.push_back({model_.elements[e].id, s[rr], s[zz], s[rz], s[th], von_mises(s)});
    }
    for (int g : model_.output.watch_gaps) {
      const GapResult& r = c.gaps[g];
      row.watch_gaps.push_back({r.id, r.modulus, r.closure, r.sigma_m});
    }
    // The end of a converged increment: the forces a force-displacement curve reads (once per
    // increment, so the cost of the reactions is that of one more residual, not of every row).
    if (v.converged) {
      if (!model_.reaction_groups.empty()) row.set_reactions = set_reactions(model_, reactions(state));
      if (model_.contact && !model_.contact->pairs.empty()) {
        for (const ContactPairResult& pair : now_->contact->surface_results(state)) {
          row.pair_forces.push_back({pair.surfaces, pair.force[0], pair.force[1]});
        }
      }
    }
    return row;
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
      // Every element's principal stresses, on the cores (the run's last work before its result).
      const MaterialPoints& points = now_->materials.points();
      s.elements.resize(model_.elements.size());
      for_each_range(model_.elements.size(), [&](std::size_t begin, std::size_t end, unsigned) {
        for (std::size_t e = begin; e < end; ++e) {
          const ElementState& es = v.centres[e];
          // An element has yielded when any of its points has, converged when all have.
          bool yielded = false;
          bool converged = true;
          for (std::size_t p = points.first(e), last = p + static_cast<std::size_t>(points.count(e)); p < last; ++p) {
            yielded = yielded || v.materials.yielded[p];
            converged = converged && v.materials.converged[p];
          }
          s.elements[e] = {model_.elements[e].id, es.stress, es.strain, principal_in_plane(es.stress),
                           von_mises(es.stress), yielded, converged};
        }
      });
      recover(state, v, s);
      s.gaps = v.contact.gaps;
      s.contact = now_->contact->surface_results(state);
      s.reactions = reactions(state);
      s.set_reactions = set_reactions(model_, s.reactions);
    }
    s.steps = step_results(state, status);
    s.message = message(state, v, status);
    return s;
  }

  /// Recovered nodal stresses and the error estimate (solver/recovery) of the evaluated state, from
  /// the laws and the material points' stresses elements[] reports.
  void recover(const RestartState& state, const Evaluation& v, Solution& s) const {
    const auto started = std::chrono::steady_clock::now();
    const IncrementSystem& now = *now_;
    StressRecovery r = recover_stresses(
        now.model, state.displacement,
        [&] {
          return PointLawsOf([&, memo = SolidMaterials::LawMemo{}](std::size_t e, std::span<Constitutive> scratch) mutable {
            return now.materials.laws(e, state.materials, memo, scratch);
          });
        },
        v.points, now.materials.points());
    for (std::size_t e = 0; e < s.elements.size(); ++e) s.elements[e].error = r.element_error[e];
    s.recovered = std::move(r.stress);
    s.error_estimate = r.estimate;
    s.recovery_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }

  /// The supports' forces in the state's last solve (reactions.hpp). A stepped run stopped right after
  /// an increment converged holds that increment's solution while the system is already the next
  /// increment's: its reactions are those of the increment it solved.
  std::vector<NodeReaction> reactions(const RestartState& state) const {
    std::vector<double> contact(state.displacement.size(), 0.0);
    now_->contact->add_nodal_forces(state, contact);
    SolidMaterials::LawMemo memo;
    if (solved_in_increment_) {
      const IncrementSystem& now = *now_;
      return support_reactions(now.model, now.dofs,
                               [&](std::size_t e, std::span<Constitutive> scratch) {
                                 return now.materials.laws(e, state.materials, memo, scratch);
                               },
                               state.displacement, contact);
    }
    const Model solved = schedule_.increment_model(schedule_.previous(*state.position));
    const DofMap dofs(solved);
    const SolidMaterials materials(solved);
    return support_reactions(solved, dofs,
                             [&](std::size_t e, std::span<Constitutive> scratch) {
                               return materials.laws(e, state.materials, memo, scratch);
                             },
                             state.displacement, contact);
  }

  /// Steps before the state's are done; the state's is done only when the run converged.
  std::vector<StepResult> step_results(const RestartState& state, RunStatus status) const {
    std::vector<StepResult> steps;
    if (!state.position) return steps;
    for (std::size_t k = 0; k < model_.steps.size(); ++k) {
      const int current = state.position->step;
      const bool done = static_cast<int>(k) < current || (static_cast<int>(k) == current && status == RunStatus::converged);
      steps.push_back({model_.steps[k].name, model_.steps[k].increments,
                       done ? StepStatus::converged : StepStatus::not_converged});
    }
    return steps;
  }

  std::string message(const RestartState& state, const Evaluation& v, RunStatus status) const {
    std::ostringstream text;
    switch (status) {
      case RunStatus::converged:
        text << "converged in " << plural(state.iteration, "iteration") << now_->contact->converged_note(state, v.contact);
        return text.str();
      case RunStatus::stopped: text << "stopped on request after iteration " << state.iteration; break;
      case RunStatus::not_converged:
        text << "not converged after " << plural(state.iteration, "iteration") << " (max_iterations " << max_iterations_
             << (state.position ? " per increment" : "") << ")";
        break;
    }
    if (state.position) {
      const Step& step = model_.steps[static_cast<std::size_t>(state.position->step)];
      text << " in step " << state.position->step + 1 << " \"" << step.name << "\", increment "
           << state.position->increment << " of " << step.increments;
    }
    if (state.iteration == 0) return text.str();
    // Say which gaps and elements still fail, and which test.
    std::vector<std::string> reasons;
    for (const GapResult& g : v.contact.gaps) {
      if (g.failure == GapFailure::none) continue;
      std::ostringstream r;
      r << "gap " << g.id << " " << describe(g.failure) << " (closure " << g.closure << " %)";
      reasons.push_back(r.str());
    }
    for (std::size_t e = 0; e < v.materials.converged.size(); ++e) {
      if (!v.materials.converged[e]) {
        reasons.push_back("element " + std::to_string(model_.elements[e].id) + " fails N-L/CONV?");
      }
    }
    if (v.materials.bimodulus_changes > 0) {
      reasons.push_back(plural(v.materials.bimodulus_changes, "element") + " switched tension/compression properties");
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
  const OrderingCache* ordering_cache_;
  int max_iterations_;
  std::optional<GapSettings> gap_settings_;  // the model's, with the restart's changes
  SurfaceContact surfaces_;                  // the rows of model.contact (the geometry's, every increment)
  bool schedule_changed_ = false;
  ContactMethodFactory make_contact_;
  LoadSchedule schedule_;
  std::size_t material_points_;           // of the model's solid elements: the material state's length
  Model increment_model_;                 // stepped models: the current increment's
  std::unique_ptr<IncrementSystem> now_;  // the current increment's system
  bool solved_in_increment_ = false;      // the state's displacements were solved with now_ (not the increment before)
  Evaluation eval_;                       // per-element buffers, reused every iteration
};

}  // namespace

Solution solve(const Model& model, IterationObserver* observer, const RestartState* resume,
               const ResumeOptions& options, const OrderingCache* cache, const ContactMethodFactory& contact) {
  GapContactAnalysis analysis(model, options, cache, contact);
  return analysis.run(observer, resume);
}

}  // namespace saasgaps
