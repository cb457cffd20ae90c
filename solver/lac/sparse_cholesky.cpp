#include "solver/lac/sparse_cholesky.hpp"

#include <cblas.h>
#include <cholmod.h>

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <chrono>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "solver/base/thread_environment.hpp"
#include "solver/lac/cholmod_memory.hpp"
#include "solver/lac/cholmod_solve.hpp"
#include "solver/lac/symbolic_cache.hpp"

namespace saasgaps {

namespace {

std::atomic<std::uint64_t> next_analysis_id{1};

std::atomic<int> max_blas_threads{static_cast<int>(std::max(1U, std::thread::hardware_concurrency()))};

/// Factorizations this big gain from parallel BLAS; smaller ones lose to thread overhead.
constexpr double parallel_blas_flops = 1.0e10;

/// METIS draws from GKlib's Mersenne twister, whose state is a static of the library: two orderings
/// computed at once on different threads (a server's workers) interleave its draws, get other
/// permutations than alone (a data race besides), and so factors that differ in their round-off:
/// the same model solved side by side with another gave other last digits than alone. Every call
/// that can reach METIS holds this lock; an ordering is computed once per pattern.
std::mutex metis_mutex;

}  // namespace

struct SparseCholesky::Impl {
  const CscPattern& pattern;
  cholmod_common common{};
  cholmod_sparse A{};  // a view of the caller's arrays: never freed by CHOLMOD
  cholmod_factor* L = nullptr;
  CholmodSolveWorkspace solve_work;  // allocated on first use and kept
  std::vector<Index> diagonal;  // position of A_jj in the value array
  std::vector<double> reference;  // |A_jj| of the last factorization
  const char* ordering_name = "METIS";
  bool ordering_cached = false;
  bool analysis_cached = false;  // the whole symbolic factor loaded (SymbolicCache)
  double ordering_seconds = 0.0;
  double flops = 0.0;         // of one numeric factorization, from the analysis
  double factor_entries = 0.0;
  const std::uint64_t analysis_id = next_analysis_id++;
  bool lent = false;  // the values were handed to UpdatableFactor::convert since the last factorization
  // The elimination tree of the supernodes, for inverse_form; derived on first use (the analysis
  // never changes): the permuted position of each original row, the supernode of each permuted
  // column, each supernode's parent (-1 at a root).
  std::vector<Index> position, supernode_of, parent;
  std::vector<double> permuted;  // forward() and backward(): a vector in the factor's order

  Impl(const CscPattern& p, std::span<const Index> groups, const OrderingCache* cache, FillOrdering fill)
      : pattern(p) {
    use_mapped_memory_for_cholmod();
    configure_solver_threads();
    cholmod_l_start(&common);
    common.print = 0;
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.final_ll = 1;
    // METIS nested dissection cuts fill and flops on 2D meshes (about 40 % against AMD); one method
    // only, so the analysis does not also try and compare AMD.
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_METIS;
    common.postorder = 1;

    A.nrow = A.ncol = static_cast<size_t>(p.n);
    A.nzmax = static_cast<size_t>(p.nnz());
    A.p = const_cast<Index*>(p.colptr.data());
    A.i = const_cast<Index*>(p.rowind.data());
    A.nz = nullptr;
    A.x = nullptr;
    A.z = nullptr;
    A.stype = 1;  // upper triangle holds the matrix
    A.itype = CHOLMOD_LONG;
    A.xtype = CHOLMOD_PATTERN;
    A.dtype = CHOLMOD_DOUBLE;
    A.sorted = 1;
    A.packed = 1;

    diagonal.resize(static_cast<size_t>(p.n));
    for (Index j = 0; j < p.n; ++j) {
      diagonal[j] = p.find(j, j);
      assert(diagonal[j] >= 0 && "every unknown couples to itself");
    }

    if (fill == FillOrdering::minimum_degree) {
      const auto started = std::chrono::steady_clock::now();
      common.method[0].ordering = CHOLMOD_AMD;
      // A scalar field's supernodes are small: merging more of them (at some explicit zeros)
      // lets BLAS-3 run on bigger blocks.
      common.nrelax[0] = 16;
      common.nrelax[1] = 64;
      common.nrelax[2] = 128;
      L = cholmod_l_analyze(&A, &common);
      ordering_name = "AMD";
      ordering_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    } else if (!groups.empty()) {
      const auto started = std::chrono::steady_clock::now();
      const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      };
      std::optional<PatternKey> key;
      if (cache != nullptr) key = pattern_key(pattern, groups, group_ordering_method());
      if (key) L = cached_analysis(*key, *cache);
      if (L != nullptr) {
        ordering_seconds = seconds();  // loading the whole analysis
      } else {
        std::vector<Index> order = cached_or_computed_group_order(groups, key ? &*key : nullptr, cache);
        ordering_seconds = seconds();
        if (!order.empty()) {
          // The same call whether the order was loaded or computed: the same factor either way.
          common.method[0].ordering = CHOLMOD_GIVEN;
          L = cholmod_l_analyze_p(&A, order.data(), nullptr, 0, &common);
          ordering_name = ordering_cached ? "METIS on node groups (cached)" : "METIS on node groups";
          if (key && L != nullptr && common.status >= CHOLMOD_OK) {
            SymbolicCache(cache->directory()).store(analysis_key(*key), *L, {common.fl, common.lnz});
          }
        }
      }
    }
    if (L == nullptr) {
      common.method[0].ordering = CHOLMOD_METIS;
      const std::lock_guard metis(metis_mutex);
      L = cholmod_l_analyze(&A, &common);
      ordering_name = "METIS";
    }
    if (L == nullptr || common.status < CHOLMOD_OK) {
      // METIS can refuse odd graphs; AMD always works.
      if (L != nullptr) cholmod_l_free_factor(&L, &common);
      common.method[0].ordering = CHOLMOD_AMD;
      L = cholmod_l_analyze(&A, &common);
      ordering_name = "AMD";
    }
    if (L == nullptr) {
      cholmod_l_finish(&common);
      throw std::runtime_error("CHOLMOD symbolic analysis failed (status " +
                               std::to_string(common.status) + ")");
    }
    if (!analysis_cached) {
      flops = common.fl;
      factor_entries = common.lnz;
    }
    allocate_values();
  }

  /// Allocates the factor's values now, as the first factorization would, and faults their pages
  /// in (about 0.35 s per GB on the development VM, 1 GB at 10^6 unknowns), here on the thread of the
  /// analysis rather than inside the first factorization. The numeric factorization clears every
  /// supernode before assembling it, so the contents do not matter. Failure is left to factorize().
  void allocate_values() {
    if (L->is_super && L->xtype == CHOLMOD_PATTERN &&
        cholmod_l_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, L, &common) && L->x != nullptr) {
      prefault_cholmod_block(L->x);
    }
  }

  /// The key of the whole analysis: the ordering's key and the settings that shape the supernodes.
  PatternKey analysis_key(const PatternKey& ordering_key) const {
    std::ostringstream settings;
    settings.precision(17);
    settings << "CHOLMOD analysis: supernodal " << common.supernodal << ", switch " << common.supernodal_switch
             << ", final_ll " << common.final_ll << ", postorder " << common.postorder << ", nrelax "
             << common.nrelax[0] << " " << common.nrelax[1] << " " << common.nrelax[2] << ", zrelax "
             << common.zrelax[0] << " " << common.zrelax[1] << " " << common.zrelax[2] << ", int64, double";
    return derived_key(ordering_key, settings.str());
  }

  /// The analysis saved under the ordering's key, or nullptr (a miss).
  cholmod_factor* cached_analysis(const PatternKey& ordering_key, const OrderingCache& cache) {
    SymbolicStatistics statistics;
    cholmod_factor* loaded =
        SymbolicCache(cache.directory()).load(analysis_key(ordering_key), pattern, statistics, common);
    if (loaded != nullptr) {
      analysis_cached = ordering_cached = true;
      ordering_name = "METIS on node groups (cached)";
      flops = statistics.flops;
      factor_entries = statistics.factor_entries;
    }
    return loaded;
  }

  /// What computes the group ordering, for the cache key: a change of method, options or library
  /// version makes a new key.
  std::string group_ordering_method() {
    int version[3] = {0, 0, 0};
    cholmod_l_version(version);
    return "METIS_NodeND on node groups, CHOLMOD defaults, postorder; CHOLMOD " + std::to_string(version[0]) + "." +
           std::to_string(version[1]) + "." + std::to_string(version[2]);
  }

  /// The group ordering from the cache when it holds a valid one, else computed (and stored).
  std::vector<Index> cached_or_computed_group_order(std::span<const Index> groups, const PatternKey* key,
                                                    const OrderingCache* cache) {
    if (cache == nullptr || key == nullptr) return group_order(groups);
    if (std::optional<std::vector<Index>> loaded = cache->load(*key, pattern.n)) {
      ordering_cached = true;
      return std::move(*loaded);
    }
    std::vector<Index> order = group_order(groups);
    if (!order.empty()) cache->store(*key, order);
    return order;
  }

  /// METIS on the graph whose vertices are the groups of unknowns, expanded to the unknowns (a
  /// group's members stay together, in order). Empty when METIS fails.
  std::vector<Index> group_order(std::span<const Index> groups) {
    const IndexGroups members = IndexGroups::of(groups);
    CscPattern graph = group_pattern(pattern, groups, members);
    const auto n = static_cast<std::size_t>(graph.n);
    cholmod_sparse G = cholmod_csc_view(n, n, graph.rowind.size(), graph.colptr.data(), graph.rowind.data(), nullptr,
                                        1, CHOLMOD_PATTERN);
    std::vector<Index> group_perm(static_cast<size_t>(graph.n));
    const std::lock_guard metis(metis_mutex);
    if (!cholmod_l_metis(&G, nullptr, 0, 0, group_perm.data(), &common)) return {};
    return expand(group_perm, members);
  }

  ~Impl() {
    cholmod_l_free_factor(&L, &common);
    solve_work.release(common);
    cholmod_l_finish(&common);
  }

  /// Factorizes `values` into L; true when positive definite and no pivot keeps less than `ratio`
  /// of its column's diagonal in `reference`. Otherwise `worst` is the column that broke down.
  bool factor_cleanly(const double* values, double ratio, Index& worst) {
    A.x = const_cast<double*>(values);
    A.xtype = CHOLMOD_REAL;
    const int ok = cholmod_l_factorize(&A, L, &common);
    A.x = nullptr;
    A.xtype = CHOLMOD_PATTERN;
    if (!ok || common.status < CHOLMOD_OK) {
      throw std::runtime_error("CHOLMOD factorization failed (status " + std::to_string(common.status) + ")");
    }
    if (common.status == CHOLMOD_NOT_POSDEF || L->minor < L->n) {
      worst = static_cast<const Index*>(L->Perm)[static_cast<Index>(L->minor)];
      return false;
    }
    worst = smallest_pivot(ratio);
    return worst < 0;
  }

  /// Where a failed factorization broke down: every mechanism, not just the first. Once one pivot
  /// is (nearly) zero, round-off divided by it pollutes the later pivots, so one factorization can
  /// name only one mechanism. The diagnosis grounds that column (a stiff spring, as an automatic
  /// single-point constraint would) and factorizes afresh, until the matrix is definite. Columns
  /// without any stiffness are named at once. Runs only after a failure.
  std::vector<Index> breakdown_columns(std::span<const double> values, Index first) {
    constexpr int max_rounds = 24;
    std::vector<double> work(values.begin(), values.end());
    double largest = 0.0;
    for (Index j = 0; j < pattern.n; ++j) largest = std::max(largest, reference[j]);
    const double ground = largest > 0.0 ? 1.0e6 * largest : 1.0;
    std::vector<Index> columns;
    const auto ground_column = [&](Index j) {
      columns.push_back(j);
      work[diagonal[j]] = ground;
    };
    for (Index j = 0; j < pattern.n; ++j) {
      if (!(values[diagonal[j]] > 0.0)) ground_column(j);
    }
    if (columns.empty()) ground_column(first);
    for (int round = 0; round < max_rounds; ++round) {
      Index worst = -1;
      if (factor_cleanly(work.data(), singular_pivot_ratio, worst)) break;
      ground_column(worst);
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    return columns;
  }

  /// The column whose pivot lost the largest share of its diagonal, if that share leaves less than
  /// `ratio` of it (supernodal LL' only); -1 when every pivot is healthy.
  Index smallest_pivot(double ratio) const {
    if (!L->is_super) return -1;
    const auto* super = static_cast<const Index*>(L->super);
    const auto* pi = static_cast<const Index*>(L->pi);
    const auto* px = static_cast<const Index*>(L->px);
    const auto* Lx = static_cast<const double*>(L->x);
    const auto* perm = static_cast<const Index*>(L->Perm);
    Index worst = -1;
    double worst_ratio = ratio;
    for (size_t s = 0; s < L->nsuper; ++s) {
      const Index first = super[s];
      const Index rows = pi[s + 1] - pi[s];
      for (Index j = first; j < super[s + 1]; ++j) {
        const double ljj = Lx[px[s] + (j - first) + (j - first) * rows];
        const Index original = perm[j];
        const double share = ljj * ljj / reference[original];
        if (!(share >= worst_ratio)) {
          worst_ratio = share;
          worst = original;
        }
      }
    }
    return worst;
  }
};

SparseCholesky::SparseCholesky(const CscPattern& pattern, std::span<const Index> groups, const OrderingCache* cache,
                               FillOrdering fill)
    : impl_(std::make_unique<Impl>(pattern, groups, cache, fill)) {}

void SparseCholesky::set_max_blas_threads(int threads) { max_blas_threads = std::max(1, threads); }

SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::factorize(std::span<const double> values) {
  Impl& m = *impl_;
  assert(static_cast<Index>(values.size()) == m.pattern.nnz());
  m.reference.resize(static_cast<size_t>(m.pattern.n));
  for (Index j = 0; j < m.pattern.n; ++j) m.reference[j] = std::abs(values[m.diagonal[j]]);
  configure_solver_threads();  // this thread may not be the one that made the analysis
  m.lent = false;  // overwritten below either way
  // Parallel BLAS for this factorization only: outside it the workers would spin beside us.
  const BlasThreads threads(m.flops >= parallel_blas_flops ? max_blas_threads.load() : 1);
  Index worst = -1;
  if (!m.factor_cleanly(values.data(), singular_pivot_ratio, worst)) {
    throw NotPositiveDefinite("the stiffness matrix is singular", m.breakdown_columns(values, worst));
  }
}

void SparseCholesky::solve(std::span<const double> b, std::span<double> x) {
  assert(!impl_->lent && "the factor was converted in place to simplicial form: factorize() again first");
  configure_solver_threads();
  cholmod_solve_into(impl_->L, b, x, impl_->solve_work, impl_->common);
}

SparseCholesky::Reach SparseCholesky::forward_columns(const SparseColumns& columns) {
  Impl& m = *impl_;
  assert(!m.lent && "the factor was converted in place to simplicial form: factorize() again first");
  const cholmod_factor& F = *m.L;
  assert(F.is_super && F.is_ll && F.xtype == CHOLMOD_REAL);
  const auto* super = static_cast<const Index*>(F.super);
  const auto* pi = static_cast<const Index*>(F.pi);
  const auto* px = static_cast<const Index*>(F.px);
  const auto* rows = static_cast<const Index*>(F.s);
  const auto* x = static_cast<const double*>(F.x);
  const auto n = static_cast<Index>(F.n);
  const auto supernodes = static_cast<Index>(F.nsuper);
  if (m.parent.empty()) {
    const auto* perm = static_cast<const Index*>(F.Perm);
    m.position.resize(static_cast<std::size_t>(n));
    m.supernode_of.resize(static_cast<std::size_t>(n));
    m.parent.assign(static_cast<std::size_t>(supernodes), -1);
    for (Index k = 0; k < n; ++k) m.position[perm[k]] = k;
    for (Index s = 0; s < supernodes; ++s) {
      for (Index j = super[s]; j < super[s + 1]; ++j) m.supernode_of[j] = s;
    }
    // A supernode's parent holds its first row below the diagonal block.
    for (Index s = 0; s < supernodes; ++s) {
      const Index width = super[s + 1] - super[s];
      if (pi[s + 1] - pi[s] > width) m.parent[s] = m.supernode_of[rows[pi[s] + width]];
    }
  }
  // The reach: every supernode on a path from a column's row to its root, and where its columns sit
  // in the compact rows of Z (supernodes in their order, which is topological: a parent comes after
  // its children). Column c of Z is nonzero only in the supernodes on its rows' paths, so a
  // supernode's rows need only the columns from the first to the last whose path passes it: the
  // paths of a contact surface's rows (in chain order) meet in a subtree for nearby rows and near
  // the root for all, so most blocks are a narrow band of the window's columns.
  const auto width = static_cast<Index>(columns.size());
  std::vector<Index> offset(static_cast<std::size_t>(supernodes), -1);
  std::vector<Index> first(static_cast<std::size_t>(supernodes), width), last(static_cast<std::size_t>(supernodes), -1);
  for (Index c = 0; c < width; ++c) {
    for (Index k = columns.start[c]; k < columns.start[c + 1]; ++k) {
      // Ranges grow towards the root (a parent's holds its children's): stop where c is inside.
      for (Index s = m.supernode_of[m.position[columns.row[k]]]; s >= 0 && !(first[s] <= c && c <= last[s]); s = m.parent[s]) {
        offset[s] = 0;
        first[s] = std::min(first[s], c);
        last[s] = std::max(last[s], c);
      }
    }
  }
  Reach reach;
  reach.columns = width;
  std::vector<Index> order;
  std::vector<std::size_t> block_of(static_cast<std::size_t>(supernodes));
  std::size_t stored = 0;
  for (Index s = 0; s < supernodes; ++s) {
    if (offset[s] < 0) continue;
    order.push_back(s);
    offset[s] = static_cast<Index>(reach.positions.size());
    block_of[s] = reach.blocks.size();
    const Index cols = super[s + 1] - super[s], band = last[s] - first[s] + 1;
    reach.blocks.push_back({offset[s], cols, first[s], band, stored});
    stored += static_cast<std::size_t>(cols) * static_cast<std::size_t>(band);
    for (Index j = super[s]; j < super[s + 1]; ++j) reach.positions.push_back(j);
  }
  reach.z.assign(stored, 0.0);
  // Row k of L (permuted position) in Z, from column `from` of the window on (within its band).
  const auto z_at = [&](Index k, Index from) {
    const Index s = m.supernode_of[k];
    const Reach::Block& b = reach.blocks[block_of[s]];
    return reach.z.data() + b.offset + static_cast<std::size_t>((k - super[s]) * b.columns + from - b.first_column);
  };
  for (Index c = 0; c < width; ++c) {
    for (Index k = columns.start[c]; k < columns.start[c + 1]; ++k) *z_at(m.position[columns.row[k]], c) += columns.value[k];
  }
  // Supernodal forward solve over the reach: the block's columns by its triangle, then its rows
  // below (which all lie in ancestors, so in the reach, whose bands hold this one's) take their
  // update, as whole rows of the band. A band is stored row after row, so BLAS sees its transpose
  // (band x cols, column-major): X L11' = B' for the block, below' = block' L21' (OpenBLAS's
  // kernels, on the one thread solves run on; a window of 949 quad8 rows at 10^6 unknowns reaches
  // 25,419 rows of L, its bands are 21 % of the dense 25,419 x 949).
  std::vector<double> below;
  for (const Index s : order) {
    const Reach::Block& b = reach.blocks[block_of[s]];
    const Index cols = b.rows, height = pi[s + 1] - pi[s], band = b.columns;
    const double* l = x + px[s];  // height x cols, column-major
    double* block = reach.z.data() + b.offset;
    cblas_dtrsm(CblasColMajor, CblasRight, CblasLower, CblasTrans, CblasNonUnit, static_cast<int>(band),
                static_cast<int>(cols), 1.0, l, static_cast<int>(height), block, static_cast<int>(band));
    if (height == cols) continue;
    const Index under = height - cols;
    below.resize(static_cast<std::size_t>(under) * static_cast<std::size_t>(band));
    cblas_dgemm(CblasColMajor, CblasNoTrans, CblasTrans, static_cast<int>(band), static_cast<int>(under),
                static_cast<int>(cols), 1.0, block, static_cast<int>(band), l + cols, static_cast<int>(height), 0.0,
                below.data(), static_cast<int>(band));
    for (Index i = 0; i < under; ++i) {
      double* target = z_at(rows[pi[s] + cols + i], b.first_column);
      const double* update = below.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(band);
      for (Index c = 0; c < band; ++c) target[c] -= update[c];
    }
  }
  return reach;
}

std::vector<double> SparseCholesky::Reach::gram() const {
  // Z'Z = the sum over the blocks of their bands' products: a symmetric rank-k product per block
  // into its band's square (a band is its transpose in column-major order), then the mirror.
  const auto m = static_cast<std::size_t>(columns);
  std::vector<double> form(m * m, 0.0);
  for (const Block& b : blocks) {
    const auto first = static_cast<std::size_t>(b.first_column);
    cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, static_cast<int>(b.columns), static_cast<int>(b.rows), 1.0,
                z.data() + b.offset, static_cast<int>(b.columns), 1.0, form.data() + first * m + first, static_cast<int>(m));
  }
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t i = j + 1; i < m; ++i) form[i * m + j] = form[j * m + i];
  }
  return form;
}

std::vector<double> SparseCholesky::inverse_form(const SparseColumns& columns) {
  return forward_columns(columns).gram();
}

void SparseCholesky::forward(std::span<const double> b, std::span<double> y) {
  Impl& m = *impl_;
  assert(!m.lent && "the factor was converted in place to simplicial form: factorize() again first");
  const auto* perm = static_cast<const Index*>(m.L->Perm);
  m.permuted.resize(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) m.permuted[k] = b[perm[k]];
  configure_solver_threads();
  cholmod_solve_into(m.L, m.permuted, y, m.solve_work, m.common, CHOLMOD_L);
}

void SparseCholesky::backward(std::span<const double> y, std::span<double> x) {
  Impl& m = *impl_;
  assert(!m.lent && "the factor was converted in place to simplicial form: factorize() again first");
  const auto* perm = static_cast<const Index*>(m.L->Perm);
  m.permuted.resize(y.size());
  configure_solver_threads();
  cholmod_solve_into(m.L, y, m.permuted, m.solve_work, m.common, CHOLMOD_Lt);
  for (std::size_t k = 0; k < x.size(); ++k) x[perm[k]] = m.permuted[k];
}

Index SparseCholesky::size() const { return impl_->pattern.n; }
double SparseCholesky::factor_nonzeros() const { return impl_->factor_entries; }
double SparseCholesky::factor_flops() const { return impl_->flops; }
const char* SparseCholesky::ordering() const { return impl_->ordering_name; }
const cholmod_factor_struct* SparseCholesky::factor() const { return impl_->L; }
cholmod_factor_struct* SparseCholesky::factor_for_conversion() {
  impl_->lent = true;
  return impl_->L;
}
std::uint64_t SparseCholesky::analysis_id() const { return impl_->analysis_id; }
bool SparseCholesky::ordering_from_cache() const { return impl_->ordering_cached; }
bool SparseCholesky::analysis_from_cache() const { return impl_->analysis_cached; }
double SparseCholesky::ordering_seconds() const { return impl_->ordering_seconds; }

}  // namespace saasgaps
