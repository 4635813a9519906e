#include <zdg/kernel/io/input_file.hpp>

#include <zdg/arith/error.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>

#include <sys/mman.h>
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

ArrivingBytes::~ArrivingBytes() {
  for (auto& p : pieces_) release(p);
}

void ArrivingBytes::release(Piece& p) {
  if (p.data != nullptr) ::munmap(p.data, p.size);
  p = Piece{};
}

std::span<std::uint8_t> ArrivingBytes::room() {
  if (size_ == claimed_) return {};
  if (pieces_.empty() || last_used_ == pieces_.back().size) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(kPiece, claimed_ - size_));
    pieces_.reserve(pieces_.size() + 1); // so that push_back cannot throw after the mmap
    void* m = ::mmap(nullptr, n, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) throw std::bad_alloc();
    pieces_.push_back(Piece{static_cast<std::uint8_t*>(m), n});
    last_used_ = 0;
  }
  auto& p = pieces_.back();
  return {p.data + last_used_, p.size - last_used_};
}

void ArrivingBytes::arrived(std::size_t n) {
  if (pieces_.empty() || n > pieces_.back().size - last_used_)
    throw std::logic_error("ArrivingBytes::arrived: more bytes than the room given");
  last_used_ += n;
  size_ += n;
}

std::vector<std::uint8_t> ArrivingBytes::take() {
  std::vector<std::uint8_t> out;
  // reserve() takes address space without touching it: resident memory grows as each piece
  // is copied in, and shrinks as each piece is unmapped.
  out.reserve(static_cast<std::size_t>(size_));
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const std::size_t used = i + 1 == pieces_.size() ? last_used_ : pieces_[i].size;
    out.insert(out.end(), pieces_[i].data, pieces_[i].data + used);
    release(pieces_[i]);
  }
  pieces_.clear();
  size_ = claimed_ = 0;
  last_used_ = 0;
  return out;
}

} // namespace zdg
