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
#include "material_state.hpp"
#include "plural.hpp"
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
  MaterialUpdate materials;
  ContactOutcome contact;
  bool converged = false;  ///< the materials' verdict AND the contact method's
};

class GapContactAnalysis {
 public:
  GapContactAnalysis(const Model& model, const ResumeOptions& options, const OrderingCache* cache,
                     const ContactMethodFactory& make_contact)
      : model_(model),
        ordering_cache_(cache),
        max_iterations_(options.max_iterations.value_or(model.solver.max_iterations)),
        gap_settings_(effective_gap_settings(model, options)),
        dofs_(model),
        materials_(model),
        system_(model, dofs_),
        contact_(make_contact({model, gap_settings_ ? &*gap_settings_ : nullptr, dofs_, system_.pattern()})),
        u_free_(static_cast<std::size_t>(dofs_.size()), 0.0) {
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

      // Strain invariance: this iteration's solid moduli. The state's material buffers take the next
      // iteration's values; the evaluation keeps the old ones to overwrite. No per-element allocation
      // from one iteration to the next.
      if (state.iteration == 0) {
        state.materials = materials_.initial();
      } else {
        std::swap(state.materials, eval.materials.next);
      }
      // K and f: the solids, then what the contact method adds (section II (a)-(d): the gap moduli).
      assemble(state);
      solve_linear_system(state);
      state.iteration += 1;
      store_displacements(state.displacement);

      evaluate(state, eval);
      contact_->check_solved(state, eval.contact);
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
    // The READ-card restart: a new schedule starts from its first value at the next iteration (-1 is
    // also what a model without gaps keeps there).
    if (schedule_changed_) s.gaps.used.schedule_step = -1;
    return s;
  }

  /// K and f of the next iteration: the solids when their moduli changed, then the contact method's
  /// part. The symbolic analysis needs only the pattern: the first time, it runs on a second core
  /// while this one assembles.
  void assemble(RestartState& state) {
    if (!cholesky_) {
      analysed_ = std::async(std::launch::async, [this] {
        return std::make_unique<SparseCholesky>(system_.pattern(), dofs_.node_of_equation(), ordering_cache_);
      });
    }
    if (!assembled_solids_ || state.materials != assembled_materials_) {
      SolidMaterials::LawMemo memo;
      system_.assemble_solids([&](std::size_t e) { return materials_.law(e, state.materials, memo); });
      assembled_materials_ = state.materials;
      assembled_solids_ = true;
    }
    contact_->begin_iteration(state, system_);
    if (analysed_.valid()) cholesky_ = analysed_.get();
  }

  /// K u = f into u_free_, contact enforced by the method.
  void solve_linear_system(RestartState& state) {
    try {
      contact_->solve(*cholesky_, system_.values(), system_.rhs(), state, u_free_);
    } catch (const NotPositiveDefinite& e) {
      throw singular_model(e);
    }
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
    u.resize(2 * model_.nodes.size());  // every entry is written below
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      for (int dir = 0; dir < 2; ++dir) {
        const Index eq = dofs_.equation(static_cast<int>(n), dir);
        u[2 * n + dir] = eq >= 0 ? u_free_[eq] : dofs_.prescribed(static_cast<int>(n), dir);
      }
    }
  }

  /// Recovers stresses of iteration K and the contact method's measurements, and judges convergence.
  /// The same code runs after a solve and after a resume, which is what makes a restart exact.
  void evaluate(RestartState& state, Evaluation& v) const {
    v.solids.resize(model_.elements.size());
    SolidMaterials::LawMemo memo;
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& el = model_.elements[e];
      const ElementData data = solid_element_data(model_, e, materials_.law(e, state.materials, memo));
      v.solids[e] = element_state(data, element_displacements(state.displacement, el.nodes, el.node_count));
    }
    materials_.update(state.materials, v.solids, model_.solver.plastic_tolerance, v.materials);
    const bool materials_converged = v.materials.nonconverged_count == 0 && v.materials.bimodulus_changes == 0;
    contact_->evaluate(state, v.contact);
    v.converged = materials_converged && v.contact.converged();
  }

  IterationRecord record(const RestartState& state, const Evaluation& v, double seconds) const {
    IterationRecord row;
    row.iteration = state.iteration;
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
    contact_->add_columns(state, row);
    for (int e : model_.output.watch_elements) {
      const Vec4& s = v.solids[e].stress;
      row.watch_elements.push_back({model_.elements[e].id, s[rr], s[zz], s[rz], s[th], von_mises(s)});
    }
    for (int g : model_.output.watch_gaps) {
      const GapResult& r = c.gaps[g];
      row.watch_gaps.push_back({r.id, r.modulus, r.closure, r.sigma_m});
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
      for (std::size_t e = 0; e < model_.elements.size(); ++e) {
        const ElementState& es = v.solids[e];
        s.elements.push_back({model_.elements[e].id, es.stress, es.strain, principal_in_plane(es.stress),
                              von_mises(es.stress), v.materials.yielded[e], v.materials.converged[e]});
      }
      s.gaps = v.contact.gaps;
    }
    s.message = message(state, v, status);
    return s;
  }

  std::string message(const RestartState& state, const Evaluation& v, RunStatus status) const {
    std::ostringstream text;
    switch (status) {
      case RunStatus::converged:
        text << "converged in " << plural(state.iteration, "iteration") << contact_->converged_note(state, v.contact);
        return text.str();
      case RunStatus::stopped: text << "stopped on request after iteration " << state.iteration; break;
      case RunStatus::not_converged:
        text << "not converged after " << plural(state.iteration, "iteration") << " (max_iterations " << max_iterations_ << ")";
        break;
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
  bool schedule_changed_ = false;
  DofMap dofs_;
  SolidMaterials materials_;
  StiffnessSystem system_;
  std::unique_ptr<ContactMethod> contact_;
  std::future<std::unique_ptr<SparseCholesky>> analysed_;  // the symbolic analysis under way
  std::unique_ptr<SparseCholesky> cholesky_;  // symbolic analysis once, at the first solve
  Evaluation eval_;                           // per-element buffers, reused every iteration
  MaterialState assembled_materials_;
  bool assembled_solids_ = false;
  std::vector<double> u_free_;
};

}  // namespace

Solution solve(const Model& model, IterationObserver* observer, const RestartState* resume,
               const ResumeOptions& options, const OrderingCache* cache, const ContactMethodFactory& contact) {
  GapContactAnalysis analysis(model, options, cache, contact);
  return analysis.run(observer, resume);
}

}  // namespace saasgaps
