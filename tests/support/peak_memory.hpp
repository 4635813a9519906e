// The growth of resident memory while a function runs, measured in a forked child process so
// that the test program's own earlier peak does not hide it: VmHWM after the call minus VmRSS
// before it (Linux /proc/self/status; a child's high-water mark starts at its resident size
// at the fork). The function returns a text (an error message, say) that comes back with it.
#pragma once

#include <cstdint>
#include <fstream>
#include <functional>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace zdg::test {

struct ChildMemory {
  bool finished = false;        ///< the child exited normally (no crash, no kill)
  std::int64_t growth_kib = -1; ///< VmHWM after - VmRSS before, in KiB
  std::string result;           ///< what the function returned
};

inline std::int64_t proc_status_kib(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(in, line)) {
    if (line.rfind(k, 0) == 0) return std::stoll(line.substr(k.size()));
  }
  return -1;
}

/// Whether a shared library whose path contains `name` is mapped into this process
/// (/proc/self/maps): the tests of libraries loaded on demand.
inline bool library_mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find(name) != std::string::npos) return true;
  return false;
}

inline ChildMemory run_in_child_measuring_memory(const std::function<std::string()>& f) {
  int fd[2];
  ChildMemory out;
  if (::pipe(fd) != 0) return out;
  const pid_t pid = ::fork();
  if (pid < 0) return out;
  if (pid == 0) {
    ::close(fd[0]);
    const std::int64_t before = proc_status_kib("VmRSS");
    std::string r;
    try {
      r = f();
    } catch (const std::exception& e) {
      r = std::string("exception: ") + e.what();
    }
    const std::int64_t after = proc_status_kib("VmHWM");
    const std::string msg = std::to_string(after - before) + "\n" + r;
    std::size_t done = 0;
    while (done < msg.size()) {
      const auto n = ::write(fd[1], msg.data() + done, msg.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::_exit(0);
  }
  ::close(fd[1]);
  std::string msg;
  char buf[4096];
  for (ssize_t n; (n = ::read(fd[0], buf, sizeof buf)) > 0;)
    msg.append(buf, static_cast<std::size_t>(n));
  ::close(fd[0]);
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return out;
  out.finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  const auto nl = msg.find('\n');
  if (nl != std::string::npos) {
    out.growth_kib = std::stoll(msg.substr(0, nl));
    out.result = msg.substr(nl + 1);
  }
  return out;
}

} // namespace zdg::test
