#include "io/mesher/gmsh_mesh.hpp"

#include <signal.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <semaphore>
#include <system_error>
#include <thread>

#include "io/mesher/geo_constants.hpp"
#include "io/mesher/mesher_protocol.hpp"
#include "io/mesher/subprocess.hpp"

namespace saasgaps::io {

namespace {

namespace fs = std::filesystem;

constexpr const char* mesher_name = "saasgaps-mesher";
constexpr std::size_t max_error_bytes = 16 * 1024;  ///< of the mesher's standard error

std::mutex limits_mutex;
MeshLimits limits_now;

/// Where the mesher may be: $SAASGAPS_MESHER, beside the running program, in ../lib/saasgaps
/// beside it (an installation), and where the build put it. The first that exists.
fs::path mesher_program() {
  std::vector<fs::path> candidates;
  if (const char* given = std::getenv("SAASGAPS_MESHER"); given != nullptr && *given != '\0') {
    candidates.emplace_back(given);
  }
  std::error_code ec;
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(program.parent_path() / mesher_name);
    candidates.push_back(program.parent_path().parent_path() / "lib" / "saasgaps" / mesher_name);
  }
  candidates.emplace_back(SAASGAPS_MESHER_PATH);
  for (const fs::path& candidate : candidates) {
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  throw MeshError(std::string("cannot find the mesher ") + mesher_name +
                  " (beside the saasgaps program, in ../lib/saasgaps, or at $SAASGAPS_MESHER)");
}

/// The counting limit on meshers running at once.
std::counting_semaphore<>& mesher_slots() {
  static std::counting_semaphore<> slots(concurrent_meshers());
  return slots;
}

class MesherSlot {
 public:
  explicit MesherSlot(const MeshLimits& limits) {
    // A slot frees within one time limit; waiting two covers a queue of one.
    if (!mesher_slots().try_acquire_for(std::chrono::seconds(2 * limits.seconds))) {
      throw MeshError("all " + std::to_string(concurrent_meshers()) + " meshers stayed busy for " +
                      std::to_string(2 * limits.seconds) + " s; try again later");
    }
  }
  ~MesherSlot() { mesher_slots().release(); }
  MesherSlot(const MesherSlot&) = delete;
  MesherSlot& operator=(const MesherSlot&) = delete;
};

std::string last_lines(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

/// The mesher's end as MeshError / MeshTooLarge, naming the limit it hit.
[[noreturn]] void throw_failure(const ProcessResult& r, const std::string& shown, const MeshLimits& limits) {
  const std::string err = last_lines(r.err);
  if (r.timed_out) {
    throw MeshError("Gmsh did not finish " + shown + " within the time limit of " + std::to_string(limits.seconds) +
                    " s (--mesh-time-limit)");
  }
  if (r.output_exceeded) {
    throw MeshTooLarge(shown + " gives a mesh larger than the limit of " + std::to_string(limits.max_nodes) +
                       " nodes allows (" + std::to_string(mesher::output_limit(limits.max_nodes)) +
                       " bytes; --max-mesh-nodes)");
  }
  switch (r.signal) {
    case 0: break;
    case SIGSYS:
      throw MeshError("Gmsh reading " + shown + " attempted a system call the sandbox forbids (running a program, "
                      "a network connection, a signal to another process): the geometry is refused");
    case SIGXCPU:
    case SIGKILL:
      throw MeshError("Gmsh did not finish " + shown + " within the CPU time limit of " +
                      std::to_string(limits.seconds) + " s (--mesh-time-limit)");
    case SIGXFSZ:
      throw MeshError("Gmsh reading " + shown + " wrote a file beyond the limit of " +
                      std::to_string(limits.file_bytes) + " bytes");
    default:
      throw MeshError("Gmsh ended abnormally reading " + shown + " (signal " + std::to_string(r.signal) + ")" +
                      (err.empty() ? "" : ": " + err));
  }
  switch (r.exit_code) {
    case mesher::too_many_nodes: throw MeshTooLarge(err + " (--max-mesh-nodes)");
    case mesher::out_of_memory:
      throw MeshTooLarge("Gmsh reading " + shown + " needed more than the memory limit of " +
                         std::to_string(limits.memory_bytes >> 20) + " MiB");
    case mesher::mesh_error:
    case mesher::no_sandbox: throw MeshError(err);
    case mesher::ok:
      throw MeshError("Gmsh ended before it read " + shown + " to the end (the geometry ends Gmsh, e.g. with Exit)");
    default:
      throw MeshError("the mesher failed on " + shown + " (exit " + std::to_string(r.exit_code) + ")" +
                      (err.empty() ? "" : ": " + err));
  }
}

}  // namespace

void set_mesh_limits(const MeshLimits& limits) {
  const std::lock_guard lock(limits_mutex);
  limits_now = limits;
}

MeshLimits mesh_limits() {
  const std::lock_guard lock(limits_mutex);
  return limits_now;
}

int concurrent_meshers() {
  return static_cast<int>(std::max(2U, std::thread::hardware_concurrency() / 2));
}

std::string dimension_name(int dim) {
  switch (dim) {
    case 0: return "dimension 0 (point)";
    case 1: return "dimension 1 (curve)";
    case 2: return "dimension 2 (surface)";
    default: return "dimension " + std::to_string(dim) + " (volume)";
  }
}

GmshMesh read_gmsh_mesh(const fs::path& path, int order, const SizeField* sizes, const MeshParameters& parameters) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw MeshError("mesh file " + path.string() + " does not exist or is not a regular file");
  }
  const std::string extension = path.extension().string();
  if (extension != ".msh" && extension != ".geo") {
    throw MeshError("mesh file " + path.string() + " must be a Gmsh mesh (.msh) or geometry (.geo) file");
  }
  // The directory the file really lies in is the mesher's whole world: a symbolic link resolved
  // here, not inside the sandbox (where its target would not exist).
  if (sizes != nullptr && extension != ".geo") {
    throw MeshError("mesh file " + path.string() + " is not a geometry (.geo): only a geometry can be re-meshed with "
                    "new element sizes");
  }
  if (!parameters.empty() && extension != ".geo") {
    throw MeshError("mesh file " + path.string() + " is not a geometry (.geo): only a geometry takes parameters");
  }
  const fs::path real = fs::canonical(path, ec);
  if (ec) throw MeshError("mesh file " + path.string() + ": " + ec.message());
  const MeshLimits limits = mesh_limits();
  ProcessSpec spec;
  spec.argv = {mesher_program().string(),
               real.parent_path().string(),
               real.filename().string(),
               path.string(),
               std::to_string(limits.max_nodes),
               std::to_string(limits.seconds),
               std::to_string(limits.memory_bytes),
               std::to_string(limits.file_bytes),
               std::to_string(order)};
  // Each parameter NAME=VALUE after the fixed arguments, the value shortest round-trip.
  for (const auto& [name, value] : parameters) {
    if (!geo_identifier(name) || !std::isfinite(value)) {
      throw MeshError("mesh parameter \"" + name + "\" must be a Gmsh name with a finite value");
    }
    std::array<char, 32> digits{};
    const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
    spec.argv.push_back(name + "=" + std::string(digits.data(), end));
  }
  // No environment: no locale to load (Gmsh reads numbers in the C locale), no HOME, no GMSH_*.
  spec.inherit_environment = false;
  // The size field goes on standard input: the mesher reads it before it confines itself, so the
  // sandbox gains no file.
  if (sizes != nullptr) spec.input = mesher::encode_sizes(*sizes, limits.max_nodes);
  spec.limit = std::chrono::seconds(limits.seconds);
  spec.max_output = mesher::output_limit(limits.max_nodes);
  spec.max_error = max_error_bytes;
  ProcessResult result;
  {
    const MesherSlot slot(limits);
    try {
      result = run_process(spec);
    } catch (const std::runtime_error& e) {
      throw MeshError(std::string("cannot start the mesher: ") + e.what());
    }
  }
  if (result.exit_code != mesher::ok || result.signal != 0 || result.out.empty()) {
    throw_failure(result, path.string(), limits);
  }
  return mesher::decode(result.out, limits.max_nodes, path.string());
}

}  // namespace saasgaps::io
