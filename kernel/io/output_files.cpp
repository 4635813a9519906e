#include <zdg/kernel/io/output_files.hpp>

#include <zdg/arith/error.hpp>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace zdg {

namespace fs = std::filesystem;

namespace {

std::atomic<unsigned> staging_counter{0};

fs::path folder_of(const fs::path& p) {
  return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

} // namespace

void check_output_path(const fs::path& path, Existing policy) {
  const std::string name = path.string();
  if (path.empty()) throw IoError("output: empty file name");
  if (!path.has_filename()) throw IoError(name + ": an output file name is needed, not a folder");
  std::error_code ec;
  const fs::path dir = folder_of(path);
  const auto dst = fs::status(dir, ec);
  if (ec || !fs::exists(dst))
    throw IoError(name + ": folder '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dst)) throw IoError(name + ": '" + dir.string() + "' is not a folder");
  const auto st = fs::symlink_status(path, ec);
  if (!ec && fs::exists(st)) {
    if (fs::is_directory(fs::status(path, ec)))
      throw IoError(name + ": is a folder, cannot be replaced by a file");
    if (policy == Existing::refuse) throw IoError(name + ": exists (use --force to replace it)");
  }
  if (::access(dir.c_str(), W_OK) != 0)
    throw IoError(name + ": folder '" + dir.string() + "' is not writable");
}

fs::path OutputSet::add(const fs::path& final_path) {
  if (committed_) throw IoError(final_path.string() + ": output set already committed");
  check_output_path(final_path, policy_);
  for (const auto& e : entries_) {
    if (fs::weakly_canonical(e.final_path) == fs::weakly_canonical(final_path))
      throw IoError(final_path.string() + ": named twice as an output");
  }
  std::string name = ".";
  name += final_path.filename().string();
  name += ".zdg-tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(staging_counter.fetch_add(1));
  const fs::path staging = folder_of(final_path) / name;
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
  // Every staging file must exist before anything is renamed.
  for (const auto& e : entries_) {
    std::error_code ec;
    if (!fs::is_regular_file(e.staging, ec))
      throw IoError(e.final_path.string() + ": nothing was written for this output");
  }
  for (const auto& e : entries_) {
    std::error_code ec;
    fs::rename(e.staging, e.final_path, ec);
    if (ec)
      throw IoError(e.final_path.string() + ": cannot move the output in place (" + ec.message() +
                    ")");
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
