#include "io/mesher/mesher_sandbox.hpp"

#include <fcntl.h>
#include <linux/capability.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>

namespace saasgaps::io {

namespace {

[[noreturn]] void fail(const std::string& what, int error = errno) {
  throw SandboxError(what + ": " + std::strerror(error));
}

void limit(int resource, rlim_t value, const char* name) {
  const rlimit r{value, value};
  if (::setrlimit(resource, &r) != 0) fail(std::string("setrlimit ") + name);
}

void set_limits(const SandboxLimits& l) {
  limit(RLIMIT_CPU, static_cast<rlim_t>(l.cpu_seconds), "RLIMIT_CPU");
  limit(RLIMIT_AS, static_cast<rlim_t>(l.memory_bytes), "RLIMIT_AS");
  limit(RLIMIT_FSIZE, static_cast<rlim_t>(l.file_bytes), "RLIMIT_FSIZE");
  limit(RLIMIT_NOFILE, static_cast<rlim_t>(l.open_files), "RLIMIT_NOFILE");
  limit(RLIMIT_CORE, 0, "RLIMIT_CORE");
}

void write_file(const char* path, const std::string& text) {
  const int fd = ::open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(std::string("open ") + path);
  const ssize_t n = ::write(fd, text.data(), text.size());
  const int error = errno;
  ::close(fd);
  if (n != static_cast<ssize_t>(text.size())) fail(std::string("write ") + path, error);
}

/// chroot needs CAP_SYS_CHROOT: root has it; anyone else gets it in a user namespace of their own
/// (mapped to their own uid and gid, so files keep their owners).
void confine_to(const std::filesystem::path& directory) {
  if (::geteuid() != 0) {
    const uid_t uid = ::geteuid();
    const gid_t gid = ::getegid();
    if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0) fail("unshare(CLONE_NEWUSER | CLONE_NEWNS)");
    write_file("/proc/self/setgroups", "deny");
    write_file("/proc/self/uid_map", std::to_string(uid) + " " + std::to_string(uid) + " 1");
    write_file("/proc/self/gid_map", std::to_string(gid) + " " + std::to_string(gid) + " 1");
  }
  if (::chroot(directory.c_str()) != 0) fail("chroot " + directory.string());
  if (::chdir("/") != 0) fail("chdir /");
}

// Landlock (linux/landlock.h), spelt out so that the rights of kernels newer than the headers can
// be asked for: filesystem rights, TCP rights (ABI 4), scopes (ABI 6).
struct LandlockRuleset {
  std::uint64_t handled_access_fs = 0;
  std::uint64_t handled_access_net = 0;
  std::uint64_t scoped = 0;
};
struct __attribute__((packed)) LandlockPathBeneath {
  std::uint64_t allowed_access = 0;
  std::int32_t parent_fd = -1;
};
constexpr std::uint64_t fs_write_file = 1U << 1, fs_read_file = 1U << 2, fs_read_dir = 1U << 3,
                        fs_remove_file = 1U << 5, fs_make_reg = 1U << 8, fs_truncate = 1U << 14;

/// Files beneath "/" (the directory) only, and with ABI 4 no TCP, with ABI 6 no signal or abstract
/// socket beyond this process. A kernel without Landlock leaves this layer out.
void restrict_with_landlock() {
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, 1U /* LANDLOCK_CREATE_RULESET_VERSION */);
  if (abi < 1) return;
  LandlockRuleset ruleset;
  const int fs_rights = abi >= 5 ? 16 : abi >= 3 ? 15 : abi >= 2 ? 14 : 13;
  ruleset.handled_access_fs = (std::uint64_t{1} << fs_rights) - 1;
  std::size_t size = sizeof ruleset.handled_access_fs;
  if (abi >= 4) {
    ruleset.handled_access_net = 3;  // BIND_TCP | CONNECT_TCP
    size += sizeof ruleset.handled_access_net;
  }
  if (abi >= 6) {
    ruleset.scoped = 3;  // ABSTRACT_UNIX_SOCKET | SIGNAL
    size += sizeof ruleset.scoped;
  }
  const int rules = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &ruleset, size, 0U));
  if (rules < 0) fail("landlock_create_ruleset");
  LandlockPathBeneath beneath;
  beneath.allowed_access = (fs_write_file | fs_read_file | fs_read_dir | fs_remove_file | fs_make_reg |
                            (abi >= 3 ? fs_truncate : 0)) &
                           ruleset.handled_access_fs;
  beneath.parent_fd = ::open("/", O_PATH | O_CLOEXEC);
  if (beneath.parent_fd < 0 ||
      ::syscall(SYS_landlock_add_rule, rules, 1 /* LANDLOCK_RULE_PATH_BENEATH */, &beneath, 0U) != 0 ||
      ::syscall(SYS_landlock_restrict_self, rules, 0U) != 0) {
    fail("landlock");
  }
  ::close(beneath.parent_fd);
  ::close(rules);
}

void drop_capabilities() {
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  std::array<__user_cap_data_struct, 2> none{};
  if (::syscall(SYS_capset, &header, none.data()) != 0) fail("capset");
}

/// The system-call policy (an allow list). Anything not named is refused with EPERM, so a Gmsh
/// feature that needs more fails with Gmsh's own error rather than a kill. No mkdir: Gmsh's
/// start-up would otherwise leave FLTK's preferences (etc/fltk/...) in the geometry's directory.
void install_seccomp() {
  scmp_filter_ctx ctx = ::seccomp_init(SCMP_ACT_ERRNO(EPERM));
  if (ctx == nullptr) throw SandboxError("seccomp_init failed");
  int rc = ::seccomp_attr_set(ctx, SCMP_FLTATR_CTL_TSYNC, 1);
  const auto add = [&](std::uint32_t action, int call, unsigned count = 0, scmp_arg_cmp arg = {}) {
    if (rc == 0) rc = count == 0 ? ::seccomp_rule_add(ctx, action, call, 0) : ::seccomp_rule_add(ctx, action, call, 1, arg);
  };
  for (const int call : {
           // files (within the chroot and Landlock's directory)
           SCMP_SYS(read), SCMP_SYS(write), SCMP_SYS(readv), SCMP_SYS(writev), SCMP_SYS(pread64), SCMP_SYS(pwrite64),
           SCMP_SYS(lseek), SCMP_SYS(close), SCMP_SYS(open), SCMP_SYS(openat), SCMP_SYS(stat), SCMP_SYS(lstat),
           SCMP_SYS(fstat), SCMP_SYS(newfstatat), SCMP_SYS(statx), SCMP_SYS(access), SCMP_SYS(faccessat),
           SCMP_SYS(faccessat2), SCMP_SYS(getdents64), SCMP_SYS(getcwd), SCMP_SYS(chdir), SCMP_SYS(fcntl),
           SCMP_SYS(dup), SCMP_SYS(dup2), SCMP_SYS(dup3), SCMP_SYS(ftruncate), SCMP_SYS(unlink), SCMP_SYS(unlinkat),
           SCMP_SYS(rename), SCMP_SYS(renameat), SCMP_SYS(renameat2), SCMP_SYS(readlink), SCMP_SYS(readlinkat), SCMP_SYS(fsync), SCMP_SYS(fdatasync),
           // memory, threads, signals to itself, time
           SCMP_SYS(brk), SCMP_SYS(mmap), SCMP_SYS(munmap), SCMP_SYS(mremap), SCMP_SYS(mprotect), SCMP_SYS(madvise),
           SCMP_SYS(futex), SCMP_SYS(set_robust_list), SCMP_SYS(rseq), SCMP_SYS(membarrier), SCMP_SYS(sched_yield),
           SCMP_SYS(sched_getaffinity), SCMP_SYS(rt_sigaction), SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigreturn),
           SCMP_SYS(sigaltstack), SCMP_SYS(exit), SCMP_SYS(exit_group), SCMP_SYS(getpid), SCMP_SYS(gettid),
           SCMP_SYS(getuid), SCMP_SYS(geteuid), SCMP_SYS(getgid), SCMP_SYS(getegid), SCMP_SYS(clock_gettime),
           SCMP_SYS(clock_getres), SCMP_SYS(gettimeofday), SCMP_SYS(time), SCMP_SYS(nanosleep),
           SCMP_SYS(clock_nanosleep), SCMP_SYS(getrlimit), SCMP_SYS(prlimit64), SCMP_SYS(getrusage), SCMP_SYS(times),
           SCMP_SYS(uname), SCMP_SYS(getrandom), SCMP_SYS(sysinfo)}) {
    add(SCMP_ACT_ALLOW, call);
  }
  // Threads only: a clone without CLONE_THREAD is a new process. clone3 passes its flags in
  // memory, which a filter cannot read: ENOSYS makes glibc fall back to clone.
  add(SCMP_ACT_ALLOW, SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, CLONE_THREAD));
  add(SCMP_ACT_KILL_PROCESS, SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
  add(SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3));
  // Signals to itself (abort, raise) only.
  const auto self = static_cast<scmp_datum_t>(::getpid());
  for (const int call : {SCMP_SYS(kill), SCMP_SYS(tgkill)}) {
    add(SCMP_ACT_ALLOW, call, 1, SCMP_A0(SCMP_CMP_EQ, self));
    add(SCMP_ACT_KILL_PROCESS, call, 1, SCMP_A0(SCMP_CMP_NE, self));
  }
  // What a hostile geometry would want: kill the mesher so that the parent can say so.
  for (const int call : {SCMP_SYS(execve), SCMP_SYS(execveat), SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(ptrace),
                         SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(connect), SCMP_SYS(tkill),
                         SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev), SCMP_SYS(chroot),
                         SCMP_SYS(mount), SCMP_SYS(unshare), SCMP_SYS(setns)}) {
    add(SCMP_ACT_KILL_PROCESS, call);
  }
  if (rc == 0) rc = ::seccomp_load(ctx);
  ::seccomp_release(ctx);
  if (rc != 0) fail("seccomp filter", -rc);
}

}  // namespace

void enter_sandbox(const std::filesystem::path& directory, const SandboxLimits& limits) {
  set_limits(limits);
  confine_to(directory);
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) fail("prctl(PR_SET_NO_NEW_PRIVS)");
  restrict_with_landlock();
  drop_capabilities();
  install_seccomp();
}

}  // namespace saasgaps::io
