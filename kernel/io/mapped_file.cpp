#include <zdg/kernel/io/mapped_file.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace zdg {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
  throw IoError(path + ": " + what + " (" + std::strerror(err) + ")");
}

std::string gib(std::uint64_t bytes) {
  return std::to_string(bytes) + " bytes";
}

} // namespace

MappedInput::MappedInput(const std::string& path) {
  size_ = input_file_size(path); // IoError for a missing file, a folder, a device
  if (size_ == 0) return;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, "cannot open for reading", errno);
  void* p = ::mmap(nullptr, static_cast<std::size_t>(size_), PROT_READ, MAP_PRIVATE, fd, 0);
  const int err = errno;
  ::close(fd);
  if (p == MAP_FAILED) fail(path, "cannot map the file into memory", err);
  ::madvise(p, static_cast<std::size_t>(size_), MADV_SEQUENTIAL);
  data_ = static_cast<const unsigned char*>(p);
}

MappedInput::~MappedInput() {
  if (data_ != nullptr) {
    ::munmap(const_cast<unsigned char*>(data_), static_cast<std::size_t>(size_));
  }
}

ReservedFile::ReservedFile(const std::string& path, std::uint64_t size) : path_(path), size_(size) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail(path, "cannot open for writing", errno);
  if (size_ == 0) return;
  // The space first: a disk too small fails here, before any work.
  if (const int err = ::posix_fallocate(fd_, 0, static_cast<off_t>(size_)); err != 0) {
    struct statvfs vfs {};
    std::string free_text;
    if (::fstatvfs(fd_, &vfs) == 0) {
      free_text = ", " + gib(static_cast<std::uint64_t>(vfs.f_bavail) * vfs.f_frsize) + " free";
    }
    ::close(fd_);
    fd_ = -1;
    ::unlink(path.c_str());
    if (err == ENOSPC || err == EFBIG) {
      throw IoError(path + ": does not fit on the disk (needs " + gib(size_) + free_text + ")");
    }
    fail(path, "cannot reserve " + gib(size_), err);
  }
}

namespace {

// pwrite / pread until every byte is through: both may transfer less than asked (signals,
// the 2 GiB cap of one call on Linux), and 0 bytes at a position inside the file is an error.
template <class Ptr, class Call>
void transfer_all(int fd, Ptr p, std::uint64_t offset, std::uint64_t bytes, const std::string& path,
                  const char* what, Call call) {
  while (bytes > 0) {
    const std::size_t chunk = static_cast<std::size_t>(std::min<std::uint64_t>(bytes, 1u << 30));
    const ssize_t n = call(fd, p, chunk, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(path, what, n < 0 ? errno : EIO);
    p += n;
    offset += static_cast<std::uint64_t>(n);
    bytes -= static_cast<std::uint64_t>(n);
  }
}

} // namespace

void ReservedFile::write(std::uint64_t offset, const void* data, std::uint64_t bytes) {
  transfer_all(fd_, static_cast<const unsigned char*>(data), offset, bytes, path_, "write error",
               ::pwrite);
}

void ReservedFile::read(std::uint64_t offset, void* data, std::uint64_t bytes) const {
  transfer_all(fd_, static_cast<unsigned char*>(data), offset, bytes, path_, "read error", ::pread);
}

void ReservedFile::finish() {
  if (fd_ >= 0) {
    const int c = ::close(fd_);
    const int err = errno;
    fd_ = -1;
    if (c != 0) fail(path_, "write error", err);
  }
}

ReservedFile::~ReservedFile() {
  if (fd_ >= 0) ::close(fd_);
}

SharedMapping::SharedMapping(const ReservedFile& file, unsigned threads) : size_(file.size_) {
  if (size_ == 0) return;
  if (file.fd_ < 0) throw IoError(file.path_ + ": cannot map a closed file");
  void* p = ::mmap(nullptr, static_cast<std::size_t>(size_), PROT_READ | PROT_WRITE, MAP_SHARED,
                   file.fd_, 0);
  if (p == MAP_FAILED) fail(file.path_, "cannot map the file into memory", errno);
  data_ = static_cast<unsigned char*>(p);
  populate_pages(data_, static_cast<std::size_t>(size_), threads);
}

SharedMapping::~SharedMapping() {
  if (data_ != nullptr) ::munmap(data_, static_cast<std::size_t>(size_));
}

namespace {

// The first number in a one-line file of /proc, or -1.
std::int64_t proc_number(const char* path) {
  std::ifstream f(path);
  std::int64_t v = -1;
  if (!(f >> v)) return -1;
  return v;
}

} // namespace

bool shared_mapping_fits(std::uint64_t bytes) {
  std::int64_t threshold = proc_number("/proc/sys/vm/dirty_background_bytes");
  if (threshold <= 0) {
    const std::int64_t ratio = proc_number("/proc/sys/vm/dirty_background_ratio");
    std::ifstream info("/proc/meminfo");
    std::string key;
    std::int64_t kb = -1;
    while (info >> key) {
      if (key == "MemAvailable:") {
        info >> kb;
        break;
      }
      info.ignore(1 << 10, '\n');
    }
    if (ratio <= 0 || kb <= 0) return false;
    threshold = kb / 100 * 1024 * ratio;
  }
  return bytes <= static_cast<std::uint64_t>(threshold) / 2;
}

template <class T>
T write_values_max(ReservedFile& out, std::uint64_t offset, const T* values, std::int64_t n,
                   unsigned threads) {
  T mx = 0;
  std::mutex mx_lock;
  constexpr std::int64_t kPiece = (std::int64_t{4} << 20) / static_cast<std::int64_t>(sizeof(T));
  parallel_for((n + kPiece - 1) / kPiece, threads, [&](std::int64_t k) {
    const std::int64_t b = k * kPiece, e = std::min(n, b + kPiece);
    T m = 0;
    for (std::int64_t i = b; i < e; ++i) m = std::max(m, values[i]);
    out.write(offset + static_cast<std::uint64_t>(b) * sizeof(T), values + b,
              static_cast<std::uint64_t>(e - b) * sizeof(T));
    const std::lock_guard<std::mutex> hold(mx_lock);
    mx = std::max(mx, m);
  });
  return mx;
}

#define ZDG_WRITE_VALUES_MAX(T)                                                                    \
  template T write_values_max<T>(ReservedFile&, std::uint64_t, const T*, std::int64_t, unsigned);
ZDG_WRITE_VALUES_MAX(std::uint8_t)
ZDG_WRITE_VALUES_MAX(std::uint16_t)
ZDG_WRITE_VALUES_MAX(std::uint32_t)
ZDG_WRITE_VALUES_MAX(std::uint64_t)
#undef ZDG_WRITE_VALUES_MAX

} // namespace zdg
