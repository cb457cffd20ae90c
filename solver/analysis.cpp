#include "analysis.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <future>
#include <sstream>

#include "contact_pairs.hpp"
#include "dof_map.hpp"
#include "element_data.hpp"
#include "errors.hpp"
#include "exact_contact.hpp"
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
  std::vector<double> gap_sigma;              ///< sigma_m per gap: normal stress across it
  std::vector<std::uint8_t> gap_touching;     ///< exact mode: some pair of the gap is in contact
  MaterialUpdate materials;
  GapVerdict gap_verdict;
  bool converged = false;
};

class GapContactAnalysis {
 public:
  GapContactAnalysis(const Model& model, const ResumeOptions& options, const OrderingCache* cache)
      : model_(model),
        ordering_cache_(cache),
        max_iterations_(options.max_iterations.value_or(model.solver.max_iterations)),
        gap_settings_(effective_gap_settings(model, options)),
        dofs_(model),
        materials_(model),
        system_(model, dofs_),
        u_free_(static_cast<std::size_t>(dofs_.size()), 0.0) {
    if (gap_settings_) gaps_.emplace(*gap_settings_);
    if (gap_settings_ && gap_settings_->method == GapMethod::exact) {
      exact_.emplace(model, dofs_, system_.pattern(), contact_pairs(model));
    }
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
      // Exact mode: every gap at the floor modulus, contact enforced by the pairs.
      GapModuli moduli = !gaps_ ? GapModuli{}
                         : exact_ ? floor_moduli()
                         : first  ? gaps_->initial()
                                  : gaps_->next(state.gaps);
      // The state's material buffers take the next iteration's values; the evaluation keeps the old
      // ones to overwrite. No per-element allocation from one iteration to the next.
      if (first) {
        state.materials = materials_.initial();
      } else {
        std::swap(state.materials, eval.materials.next);
      }

      solve_linear_system(state.materials, moduli, state.contact);

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
      if (exact_) check_contact_has_solution(state, eval);
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

  /// Exact mode: the floor modulus (the schedule's last value) in every gap, M and N alike.
  GapModuli floor_moduli() const {
    GapModuli m;
    m.tensile = gaps_->floor_modulus();
    m.normal.assign(gap_settings_->elements.size(), m.tensile);
    m.schedule_step = static_cast<int>(gap_settings_->tensile_schedule.size()) - 1;
    return m;
  }

  /// Assembles what changed and solves K u = f into u_free_ (exact mode: the contact problem, with
  /// `contact` its warm start and its result).
  void solve_linear_system(const MaterialState& solid, const GapModuli& moduli, ContactState& contact) {
    // The symbolic analysis needs only the pattern: the first time, it runs on a second core while
    // this one assembles.
    std::future<std::unique_ptr<SparseCholesky>> analysed;
    if (!cholesky_) {
      analysed = std::async(std::launch::async, [this] {
        return std::make_unique<SparseCholesky>(system_.pattern(), dofs_.node_of_equation(), ordering_cache_);
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
      if (exact_) {
        contact_report_ = exact_->solve(*cholesky_, system_.values(), system_.rhs(), contact, u_free_);
        load_norm_ = 0.0;
        for (double f : system_.rhs()) load_norm_ += std::abs(f);
      } else {
        cholesky_->factorize(system_.values());
        cholesky_->solve(system_.rhs(), u_free_);
      }
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
      v.gap_sigma.resize(elements.size());
      for (std::size_t g = 0; g < elements.size(); ++g) {
        const ElementData data = gap_element_data(model_, g, gaps_->law(g, state.gaps.used, model_.analysis));
        v.gaps[g] = element_state(data, element_displacements(state.displacement, elements[g].nodes,
                                                              elements[g].node_count));
        v.gap_strain[g] = normal_component(v.gaps[g].strain, elements[g].angle_deg, 1.0);
        v.gap_sigma[g] = normal_component(v.gaps[g].stress, elements[g].angle_deg, 2.0);
      }
      if (exact_) measure_contact(state, v);
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
      v.gap_verdict = exact_ ? exact_verdict(v) : gaps_->test(state.gaps);
      converged = converged && v.gap_verdict.all_converged();
    }
    v.converged = converged;
  }

  /// Exact mode: closures from the pairs' gap functions, sigma_m = the floor spring's stress minus the
  /// contact pressure. A pair's pressure is its force over the face area it stands for, and a gap's
  /// the area-weighted mean of its pairs': a uniform pressure p gives every pair lambda_i = p area_i,
  /// hence exactly p on every gap.
  void measure_contact(const RestartState& state, Evaluation& v) const {
    const ContactPairs& cp = exact_->pairs();
    const bool solved = state.contact.force.size() == cp.pairs.size();
    v.gap_touching.assign(v.gap_strain.size(), 0);
    for (std::size_t g = 0; g < v.gap_strain.size(); ++g) {
      double area = 0.0, force = 0.0, closed = 0.0, initial = 0.0;
      for (int k = 0; k < cp.share_count[g]; ++k) {
        const PairShare& share = cp.of_gap[g][k];
        const ContactPair& pair = cp.pairs[share.pair];
        area += share.area;
        initial += share.area * pair.g0;
        closed += share.area * (pair.g0 - exact_->gap(share.pair, state.displacement));
        if (!solved) continue;
        force += share.area * state.contact.force[share.pair] / pair.area;
        v.gap_touching[g] = v.gap_touching[g] || state.contact.active[share.pair];
      }
      v.gap_strain[g] = -closed / initial;
      v.gap_sigma[g] -= force / area;
    }
  }

  GapVerdict exact_verdict(const Evaluation& v) const {
    GapVerdict verdict;
    const std::size_t n = v.gap_strain.size();
    verdict.failure.assign(n, GapFailure::none);
    verdict.converged.assign(n, true);
    double closed_sum = 0.0;
    for (std::size_t g = 0; g < n; ++g) {
      const double closure = -100.0 * v.gap_strain[g];
      verdict.max_closure = g == 0 ? closure : std::max(verdict.max_closure, closure);
      if (v.gap_touching[g]) {
        ++verdict.closed;
        closed_sum += closure;
      }
    }
    verdict.average_closure = verdict.closed > 0 ? closed_sum / verdict.closed : 0.0;
    return verdict;
  }

  /// The floor springs of open gaps are there to restrain bodies held only by gaps, not to carry
  /// load. When they carry a real share of it, a body is being pushed away from every support and
  /// the contact problem has no solution (or the floor modulus is not negligible).
  void check_contact_has_solution(const RestartState& state, const Evaluation& v) const {
    const ContactPairs& cp = exact_->pairs();
    constexpr double largest_floor_share = 0.01;
    double carried = load_norm_;
    for (double lambda : state.contact.force) carried += std::max(0.0, lambda);
    std::vector<std::pair<double, std::size_t>> open;  // floor force, gap
    double open_force = 0.0;
    for (std::size_t g = 0; g < v.gap_sigma.size(); ++g) {
      if (v.gap_touching[g]) continue;
      double area = 0.0;
      for (int k = 0; k < cp.share_count[g]; ++k) area += cp.of_gap[g][k].area;
      const double force = std::abs(v.gap_sigma[g]) * area;
      open_force += force;
      open.emplace_back(force, g);
    }
    if (!(open_force > largest_floor_share * carried)) return;
    std::sort(open.begin(), open.end(), std::greater<>());
    std::ostringstream text;
    text << "the contact problem has no solution: " << 100.0 * open_force / carried
         << " % of the load is carried by the floor stiffness of gaps that do not touch (";
    const std::size_t shown = std::min<std::size_t>(open.size(), 6);
    for (std::size_t k = 0; k < shown; ++k) {
      const GapElement& gap = gap_settings_->elements[open[k].second];
      text << (k ? "; " : "") << "gap " << gap.id << " at nodes";
      for (int a = 0; a < gap.node_count; ++a) text << ' ' << model_.nodes[gap.nodes[a]].id;
    }
    if (open.size() > shown) text << "; and " << open.size() - shown << " more";
    text << "): a body is pushed away from every support, or the floor modulus " << gaps_->floor_modulus()
         << " (the last tensile_schedule value) is not negligible";
    throw SolverError(text.str());
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
      if (exact_) {
        row.contact_pairs = contact_report_.pairs_in_contact;
        row.complementarity = contact_report_.complementarity;
        row.active_set_iterations = contact_report_.active_set_iterations;
      }
    }
    for (int e : model_.output.watch_elements) {
      const Vec4& s = v.solids[e].stress;
      row.watch_elements.push_back({model_.elements[e].id, s[rr], s[zz], s[rz], s[th], von_mises(s)});
    }
    for (int g : model_.output.watch_gaps) {
      row.watch_gaps.push_back({gap_settings_->elements[g].id, state.gaps.used.normal[g],
                                -100.0 * v.gap_strain[g], v.gap_sigma[g]});
    }
    return row;
  }

  GapState gap_state(const Evaluation& v, std::size_t g) const {
    if (exact_) return v.gap_touching[g] ? GapState::closed : GapState::open;
    const double eps = v.gap_strain[g];
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
                          v.gap_sigma[g], gap_state(v, g),
                          v.gap_verdict.converged[g], v.gap_verdict.failure[g]});
      }
    }
    s.message = message(state, v, status);
    return s;
  }

  std::string message(const RestartState& state, const Evaluation& v, RunStatus status) const {
    std::ostringstream text;
    switch (status) {
      case RunStatus::converged:
        text << "converged in " << state.iteration << " iterations";
        if (exact_) {
          text << " (exact contact: " << state.history.back().contact_pairs << " of " << exact_->pairs().pairs.size()
               << " node pairs in contact, complementarity residual " << state.history.back().complementarity << ")";
        } else if (gaps_) {
          text << loaded_open_gaps(state, v);
        }
        return text.str();
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

  /// The classic method's blind spot: gaps stiffened above the floor modulus that stopped short of
  /// contact yet carry a real share of the largest gap pressure. Their pressures are where the
  /// iteration stopped, not the contact answer. (A gap at the floor modulus carries only the
  /// negligible spring the exact mode keeps too.) Empty when there are none.
  std::string loaded_open_gaps(const RestartState& state, const Evaluation& v) const {
    constexpr double share = 0.01;
    double largest = 0.0;
    for (double sigma : v.gap_sigma) largest = std::max(largest, -sigma);
    if (!(largest > 0.0)) return {};
    const double touching = 1.0 - gap_settings_->closure_tolerance;
    std::size_t count = 0, worst = 0;
    for (std::size_t g = 0; g < v.gap_sigma.size(); ++g) {
      const double eps = v.gap_strain[g];
      const bool stiffened = state.gaps.used.normal[g] > gaps_->floor_modulus();
      if (!(stiffened && eps < 0.0 && -eps < touching && -v.gap_sigma[g] > share * largest)) continue;
      if (count == 0 || v.gap_sigma[g] < v.gap_sigma[worst]) worst = g;
      ++count;
    }
    if (count == 0) return {};
    std::ostringstream text;
    text << "; warning: " << count << " gaps do not touch (closure below " << 100.0 * touching
         << " %) yet carry more than " << 100.0 * share << " % of the largest gap pressure (gap "
         << gap_settings_->elements[worst].id << ": closure " << -100.0 * v.gap_strain[worst] << " %, sigma_m "
         << v.gap_sigma[worst] << "); the classic stopping rule accepts them, so their pressures and the stresses "
         << "near them are approximate: \"method\": \"exact\" in gaps solves the contact exactly";
    return text.str();
  }

  const Model& model_;
  const OrderingCache* ordering_cache_;
  int max_iterations_;
  std::optional<GapSettings> gap_settings_;
  std::optional<GapClosure> gaps_;
  bool schedule_changed_ = false;
  DofMap dofs_;
  SolidMaterials materials_;
  StiffnessSystem system_;
  std::optional<ExactContact> exact_;          // exact mode only
  ContactReport contact_report_;              // of the last contact solve
  double load_norm_ = 0.0;                    // |f|_1 of the last contact solve
  std::unique_ptr<SparseCholesky> cholesky_;  // symbolic analysis once, at the first solve
  Evaluation eval_;                           // per-element buffers, reused every iteration
  MaterialState assembled_materials_;
  bool assembled_solids_ = false;
  std::vector<double> u_free_;
};

}  // namespace

Solution solve(const Model& model, IterationObserver* observer, const RestartState* resume,
               const ResumeOptions& options, const OrderingCache* cache) {
  GapContactAnalysis analysis(model, options, cache);
  return analysis.run(observer, resume);
}

}  // namespace saasgaps
