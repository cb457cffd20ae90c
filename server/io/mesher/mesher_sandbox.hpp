#pragma once
/// The confinement saasgaps-mesher puts itself in before Gmsh reads an untrusted geometry. Layers,
/// each enough against a different way out (docs/import.md, "Why a geometry can do no harm"):
///
/// 1. Resource limits: CPU seconds, address space, size of any file written, open files, no core.
/// 2. The file system is the geometry's own directory: chroot into it (as root directly, otherwise
///    inside a new user and mount namespace), so "/" and ".." end there.
/// 3. Landlock, where the kernel has it: files beneath that directory only, no TCP, no signals or
///    abstract sockets outside the process (a second wall should the first have a gap).
/// 4. Every capability dropped and no_new_privs set: root inside the chroot cannot leave it.
/// 5. A seccomp filter that allows the system calls reading files and meshing need, kills the
///    process on exec, fork, non-thread clone, sockets, ptrace and signals to other processes, and
///    refuses everything else with EPERM.
///
/// Any layer but Landlock failing is SandboxError: the caller must then not read the file.

#include <cstddef>
#include <filesystem>
#include <stdexcept>

namespace saasgaps::io {

class SandboxError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SandboxLimits {
  int cpu_seconds = 60;
  std::size_t memory_bytes = std::size_t{2} << 30;
  std::size_t file_bytes = std::size_t{64} << 20;
  int open_files = 64;
};

/// Confines the calling (single-threaded) process to `directory` as described above; afterwards
/// the directory is "/". Descriptors already open (standard output) stay usable.
void enter_sandbox(const std::filesystem::path& directory, const SandboxLimits& limits);

}  // namespace saasgaps::io
