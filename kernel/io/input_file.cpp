#include <zdg/kernel/io/input_file.hpp>

#include <zdg/arith/error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <sys/stat.h>

namespace zdg {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// stat() of an input: IoError unless it is a regular file or (when allowed) a pipe.
struct stat input_status(const std::string& path, bool allow_pipe) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ENOENT) throw IoError(path + ": cannot open (no such file)");
    throw IoError(path + ": cannot open (" + std::strerror(err) + ")");
  }
  if (S_ISDIR(st.st_mode)) throw IoError(path + ": is a folder, not a file");
  if (!S_ISREG(st.st_mode) && !(allow_pipe && S_ISFIFO(st.st_mode))) {
    throw IoError(path + ": not a regular file (a device or a socket cannot be read as input)");
  }
  return st;
}

} // namespace

std::uint64_t input_file_size(const std::string& path) {
  return static_cast<std::uint64_t>(input_status(path, false).st_size);
}

std::string read_input_file(const std::string& path, std::uint64_t max_bytes) {
  const struct stat st = input_status(path, true);
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw IoError(path + ": cannot open (" + std::strerror(errno) + ")");
  auto too_large = [&]() {
    return IoError(path + ": larger than " + std::to_string(max_bytes) +
                   " bytes, the limit for an input file");
  };
  std::string data;
  if (S_ISREG(st.st_mode)) {
    if (static_cast<std::uint64_t>(st.st_size) > max_bytes) throw too_large();
    data.reserve(static_cast<std::size_t>(st.st_size));
  }
  char buf[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buf, 1, sizeof buf, f.get());
    if (n > 0) {
      if (data.size() + n > max_bytes) throw too_large();
      data.append(buf, n);
    }
    if (n < sizeof buf) break;
  }
  if (std::ferror(f.get()) != 0)
    throw IoError(path + ": read error (" + std::strerror(errno) + ")");
  return data;
}

} // namespace zdg
