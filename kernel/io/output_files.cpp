#include <zdg/kernel/io/output_files.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <deque>
#include <fstream>
#include <mutex>
#include <optional>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>
#if defined(__linux__)
#include <linux/fs.h>
#endif

namespace zdg {

namespace fs = std::filesystem;

namespace detail {
void (*before_output_rename)(const fs::path& final_path) = nullptr;
} // namespace detail

namespace {

std::atomic<unsigned> staging_counter{0};

constexpr std::string_view kStagingTag = ".zdg-tmp-";
constexpr std::string_view kBackupTag = ".zdg-old-";

fs::path folder_of(const fs::path& p) {
  return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

// ".NAME<tag>PID-K" in the folder of `final_path`, K unique in this process.
fs::path hidden_name(const fs::path& final_path, std::string_view tag) {
  std::string name = ".";
  name += final_path.filename().string();
  name += tag;
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(staging_counter.fetch_add(1));
  return folder_of(final_path) / name;
}

std::optional<struct stat> lstat_of(const fs::path& p) {
  struct stat st {};
  if (::lstat(p.c_str(), &st) != 0) return std::nullopt;
  return st;
}

std::optional<struct stat> stat_of(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) return std::nullopt;
  return st;
}

bool same_inode(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// The identity of an output as a directory entry: the canonical folder and the file name (a
// folder that does not exist: the absolute, normalized spelling).
fs::path entry_of(const fs::path& p) {
  std::error_code ec;
  const fs::path dir = fs::canonical(folder_of(p), ec);
  if (!ec) return dir / p.filename();
  const fs::path abs = fs::absolute(p, ec);
  return ec ? p.lexically_normal() : abs.lexically_normal();
}

// The inode flags (chattr) of a file or folder, where the file system has them.
std::optional<long> inode_flags(const fs::path& p, bool folder) {
#if defined(__linux__) && defined(FS_IOC_GETFLAGS)
  const int fd = ::open(p.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC | O_NOFOLLOW |
                                       (folder ? O_DIRECTORY : 0));
  if (fd < 0) return std::nullopt;
  int flags = 0; // the kernel reads and writes an int, whatever the macro's type says
  const int r = ::ioctl(fd, FS_IOC_GETFLAGS, &flags);
  ::close(fd);
  if (r != 0) return std::nullopt;
  return flags;
#else
  (void)p;
  (void)folder;
  return std::nullopt;
#endif
}

#if defined(__linux__) && defined(FS_IOC_GETFLAGS)
constexpr long kImmutable = FS_IMMUTABLE_FL, kAppendOnly = FS_APPEND_FL;
#else
constexpr long kImmutable = 0, kAppendOnly = 0;
#endif

bool has_flag(const std::optional<long>& flags, long which) {
  return flags && (*flags & which) != 0;
}

// Every check of an output that needs no other output: see check_output_path.
void check_target(const fs::path& path, Existing policy) {
  const std::string name = path.string();
  if (path.empty()) throw IoError("output: empty file name");
  if (!path.has_filename()) throw IoError(name + ": an output file name is needed, not a folder");
  const fs::path dir = folder_of(path);
  std::error_code ec;
  const auto dst = fs::status(dir, ec);
  if (ec || !fs::exists(dst))
    throw IoError(name + ": folder '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dst)) throw IoError(name + ": '" + dir.string() + "' is not a folder");
  const auto dir_flags = inode_flags(dir, true);
  if (has_flag(dir_flags, kImmutable))
    throw IoError(name + ": folder '" + dir.string() + "' is immutable (chattr +i)");
  const auto target = lstat_of(path);
  if (!target && errno != ENOENT)
    throw IoError(name + ": cannot be examined (" + std::strerror(errno) + ")");
  if (target) {
    const auto followed = stat_of(path);
    if (S_ISDIR(target->st_mode) || (followed && S_ISDIR(followed->st_mode)))
      throw IoError(name + ": is a folder, cannot be replaced by a file");
    if (!S_ISREG(target->st_mode) && !S_ISLNK(target->st_mode))
      throw IoError(name + ": exists and is not a regular file (a device, pipe or socket), "
                           "cannot be replaced");
    if (policy == Existing::refuse) throw IoError(name + ": exists (use --force to replace it)");
    if (S_ISREG(target->st_mode) && has_flag(inode_flags(path, false), kImmutable | kAppendOnly))
      throw IoError(name + ": is immutable or append-only (chattr +i / +a), cannot be replaced");
    if (has_flag(dir_flags, kAppendOnly))
      throw IoError(name + ": folder '" + dir.string() +
                    "' is append-only (chattr +a): an existing file cannot be replaced");
    const auto folder = stat_of(dir);
    const uid_t me = ::geteuid();
    if (folder && (folder->st_mode & S_ISVTX) != 0 && me != 0 && target->st_uid != me &&
        folder->st_uid != me)
      throw IoError(name + ": belongs to another user in a sticky folder ('" + dir.string() +
                    "'), cannot be replaced");
  }
  if (::faccessat(AT_FDCWD, dir.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
    throw IoError(name + ": folder '" + dir.string() + "' is not writable");
}

// Parses ".NAME<tag>PID-K": the PID and NAME, or nothing.
std::optional<std::pair<pid_t, std::string>> parse_hidden(const std::string& file,
                                                          std::string_view tag) {
  if (file.size() < 2 || file[0] != '.') return std::nullopt;
  const std::size_t at = file.rfind(tag);
  if (at == std::string::npos || at < 2) return std::nullopt;
  const std::string rest = file.substr(at + tag.size());
  const std::size_t dash = rest.find('-');
  if (dash == 0 || dash == std::string::npos || dash + 1 == rest.size() || dash > 9)
    return std::nullopt;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (i != dash && (rest[i] < '0' || rest[i] > '9')) return std::nullopt;
  }
  const long pid = std::stol(rest.substr(0, dash)); // at most 9 digits
  if (pid <= 0 || pid > INT_MAX) return std::nullopt;
  return std::make_pair(static_cast<pid_t>(pid), file.substr(1, at - 1));
}

bool process_gone(pid_t pid) {
  return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

// Removes what killed zdg processes left in `dir`: their staging files, and their backups
// (put back in place where the output is missing).
void remove_stale_files(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    found.push_back(it->path());
  for (const auto& p : found) {
    const std::string file = p.filename().string();
    const auto st = lstat_of(p);
    if (!st || !S_ISREG(st->st_mode)) continue;
    if (const auto s = parse_hidden(file, kStagingTag); s && process_gone(s->first)) {
      ::unlink(p.c_str());
    } else if (const auto b = parse_hidden(file, kBackupTag); b && process_gone(b->first)) {
      const fs::path output = dir / b->second;
      if (lstat_of(output))
        ::unlink(p.c_str());
      else
        ::rename(p.c_str(), output.c_str());
    }
  }
}

// Staging path -> output path of the recent outputs, for name_outputs.
struct StagingNames {
  std::mutex mutex;
  std::deque<std::pair<std::string, std::string>> pairs;
};

StagingNames& staging_names() {
  static StagingNames names;
  return names;
}

void remember_staging(const fs::path& staging, const fs::path& final_path) {
  auto& names = staging_names();
  const std::lock_guard lock(names.mutex);
  names.pairs.emplace_back(staging.string(), final_path.string());
  names.pairs.emplace_back(staging.filename().string(), final_path.filename().string());
  while (names.pairs.size() > 2 * 4096) names.pairs.pop_front();
}

} // namespace

void check_output_path(const fs::path& path, Existing policy) {
  check_target(path, policy);
}

bool same_output(const fs::path& a, const fs::path& b) {
  if (entry_of(a) == entry_of(b)) return true;
  const auto sa = lstat_of(a), sb = lstat_of(b);
  return sa && sb && same_inode(*sa, *sb);
}

void check_not_input(const fs::path& input, const fs::path& output) {
  if (input.empty() || output.empty()) return;
  const auto si = stat_of(input), so = stat_of(output);
  if ((si && so && same_inode(*si, *so)) || entry_of(input) == entry_of(output))
    throw IoError("output " + output.string() + " is the input file " + input.string() +
                  ": refusing to overwrite it");
}

std::string name_outputs(std::string message) {
  auto& names = staging_names();
  const std::lock_guard lock(names.mutex);
  // Longest first, so that a staging path is replaced whole before a shorter name inside it;
  // again until nothing changes (a staging file of a staging file).
  std::vector<const std::pair<std::string, std::string>*> order;
  for (const auto& p : names.pairs) {
    if (message.find(p.first) != std::string::npos) order.push_back(&p);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](auto* x, auto* y) { return x->first.size() > y->first.size(); });
  for (int round = 0; round < 8 && !order.empty(); ++round) {
    bool changed = false;
    for (const auto* p : order) {
      for (std::size_t at; (at = message.find(p->first)) != std::string::npos;) {
        message.replace(at, p->first.size(), p->second);
        changed = true;
      }
    }
    if (!changed) break;
  }
  return message;
}

fs::path OutputSet::add(const fs::path& final_path) {
  if (committed_) throw IoError(final_path.string() + ": output set already committed");
  for (const auto& e : entries_) {
    if (same_output(e.final_path, final_path))
      throw IoError(e.final_path.string() + " and " + final_path.string() +
                    " are the same file: each output needs its own file");
  }
  check_target(final_path, policy_);
  const fs::path entry = entry_of(final_path);
  const fs::path dir = entry.parent_path();
  if (std::find(cleaned_.begin(), cleaned_.end(), dir) == cleaned_.end()) {
    remove_stale_files(dir);
    cleaned_.push_back(dir);
  }
  const fs::path staging = hidden_name(final_path, kStagingTag);
  remember_staging(staging, final_path);
  entries_.push_back({final_path, staging});
  return staging;
}

void OutputSet::drop(const fs::path& final_path) {
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->final_path == final_path) {
      std::error_code ec;
      fs::remove(it->staging, ec);
      entries_.erase(it);
      return;
    }
  }
  throw IoError(final_path.string() + ": not an output of this set");
}

void OutputSet::commit() {
  if (committed_) throw IoError("output set already committed");
  // Every staging file must exist, and every output must still be replaceable, before
  // anything is renamed.
  for (const auto& e : entries_) {
    const auto st = lstat_of(e.staging);
    if (!st || !S_ISREG(st->st_mode))
      throw IoError(e.final_path.string() + ": nothing was written for this output");
    check_target(e.final_path, policy_);
  }
  // Each output in turn: its old file kept under a backup name, the new one renamed in. On a
  // failure, what was replaced is put back.
  struct Step {
    const Entry* entry = nullptr;
    fs::path backup; // empty: the output did not exist
    bool moved_aside = false, placed = false;
  };
  std::vector<Step> steps;
  steps.reserve(entries_.size());
  auto undo = [&steps]() {
    std::string lost;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
      const fs::path& out = it->entry->final_path;
      if (it->backup.empty()) {
        if (it->placed) ::unlink(out.c_str());
      } else if (it->placed || it->moved_aside) {
        if (::rename(it->backup.c_str(), out.c_str()) != 0)
          lost += "; the old " + out.string() + " could not be put back (" + std::strerror(errno) +
                  "): it is " + it->backup.string();
      } else {
        ::unlink(it->backup.c_str());
      }
    }
    return lost;
  };
  for (const auto& e : entries_) {
    Step& s = steps.emplace_back();
    s.entry = &e;
    const std::string name = e.final_path.string();
    if (lstat_of(e.final_path)) {
      s.backup = hidden_name(e.final_path, kBackupTag);
      if (::link(e.final_path.c_str(), s.backup.c_str()) != 0) {
        if (::rename(e.final_path.c_str(), s.backup.c_str()) != 0) {
          const std::string why = std::strerror(errno);
          s.backup.clear();
          throw IoError(name + ": cannot keep the old file while replacing it (" + why +
                        "); nothing was replaced" + undo());
        }
        s.moved_aside = true;
      }
    }
    if (detail::before_output_rename != nullptr) detail::before_output_rename(e.final_path);
    if (::rename(e.staging.c_str(), e.final_path.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      const std::string lost = undo();
      throw IoError(name + ": cannot move the output in place (" + why + ")" +
                    (lost.empty() ? "; every output was left as it was" : lost));
    }
    s.placed = true;
  }
  for (const auto& s : steps) {
    if (!s.backup.empty()) ::unlink(s.backup.c_str());
  }
  committed_ = true;
}

OutputSet::~OutputSet() {
  if (committed_) return;
  for (const auto& e : entries_) {
    std::error_code ec;
    fs::remove(e.staging, ec);
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes, Existing policy) {
  OutputSet set(policy);
  const fs::path staging = set.add(path);
  {
    std::ofstream out(staging, std::ios::binary | std::ios::trunc);
    if (!out) throw IoError(path + ": cannot write (" + std::strerror(errno) + ")");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw IoError(path + ": write failed (disk full?)");
  }
  set.commit();
}

} // namespace zdg
