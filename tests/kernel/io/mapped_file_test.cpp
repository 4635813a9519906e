#include <zdg/kernel/io/mapped_file.hpp>

#include <zdg/arith/error.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace zdg {
namespace {

namespace fs = std::filesystem;

TEST(MappedFile, WhatIsWrittenThroughTheMapIsInTheFile) {
  const fs::path dir = test::scratch_dir("mapped");
  const std::string path = (dir / "out.bin").string();
  {
    ReservedFile out(path, 100'000);
    ASSERT_EQ(out.size(), 100'000u);
    std::vector<unsigned char> bytes(100'000);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 7);
    out.write(50'000, bytes.data() + 50'000, 50'000); // any order, at offsets
    out.write(0, bytes.data(), 50'000);
    std::vector<unsigned char> back(1000);
    out.read(49'500, back.data(), back.size());
    EXPECT_TRUE(std::equal(back.begin(), back.end(), bytes.begin() + 49'500));
    out.finish();
  }
  EXPECT_EQ(fs::file_size(path), 100'000u);
  MappedInput in(path);
  ASSERT_EQ(in.size(), 100'000u);
  for (std::size_t i = 0; i < in.size(); ++i) {
    ASSERT_EQ(in.data()[i], static_cast<unsigned char>(i * 7)) << i;
  }
  // An existing file is replaced (truncated first), an empty one maps to nothing.
  {
    ReservedFile out(path, 0);
    out.finish();
  }
  EXPECT_EQ(fs::file_size(path), 0u);
  EXPECT_EQ(MappedInput(path).size(), 0u);
  fs::remove_all(dir);
}

// SharedMapping: bytes stored through the mapping (a pattern over 5 MiB, past the 4 MiB under
// which populate_pages does nothing, and a small file) are the file's bytes once it is
// unmapped and closed, next to a header written with write(); an empty file maps to nothing.
TEST(MappedFile, WhatIsStoredThroughASharedMappingIsInTheFile) {
  const fs::path dir = test::scratch_dir("mapped-shared");
  const std::string path = (dir / "out.bin").string();
  for (const std::uint64_t size : {std::uint64_t{5} << 20, std::uint64_t{1000}, std::uint64_t{0}}) {
    {
      ReservedFile out(path, size);
      const unsigned char head[4] = {'z', 'd', 'g', '!'};
      if (size > 0) out.write(0, head, 4);
      {
        const SharedMapping map(out, 3);
        ASSERT_EQ(map.data() == nullptr, size == 0);
        if (size > 0) {
          EXPECT_EQ(map.data()[2], 'g'); // the write is seen through the mapping
        }
        for (std::uint64_t i = 4; i < size; ++i) map.data()[i] = static_cast<unsigned char>(i * 13);
      }
      out.finish();
    }
    ASSERT_EQ(fs::file_size(path), size);
    MappedInput in(path);
    for (std::uint64_t i = 0; i < size; ++i) {
      const unsigned char expect = i < 4 ? "zdg!"[i] : static_cast<unsigned char>(i * 13);
      ASSERT_EQ(in.data()[i], expect) << size << " " << i;
    }
  }
  // An output larger than the address space never fits.
  EXPECT_FALSE(shared_mapping_fits(std::uint64_t{1} << 62));
  fs::remove_all(dir);
}

// write_values_max (the lean transform command's write): the file holds the values after the
// offset, byte for byte, and the result is their maximum (oracle: std::max_element), for a
// count that spans several 4 MiB pieces and a partial last one, by 1 and 3 workers, and for
// no values at all.
template <class T>
void check_write_values_max(std::int64_t n, unsigned threads, const std::string& path) {
  std::vector<T> v(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<T>(i * 2654435761u);
  const std::uint64_t offset = 128, bytes = static_cast<std::uint64_t>(n) * sizeof(T);
  ReservedFile out(path, offset + bytes);
  const T mx = write_values_max<T>(out, offset, v.data(), n, threads);
  out.finish();
  EXPECT_EQ(mx, v.empty() ? T{0} : *std::max_element(v.begin(), v.end())) << n;
  MappedInput in(path);
  ASSERT_EQ(in.size(), offset + bytes);
  if (bytes > 0) { // memcmp takes no null pointer, even for 0 bytes (an empty vector's data())
    EXPECT_EQ(std::memcmp(in.data() + offset, v.data(), bytes), 0) << n << " " << threads;
  }
}

TEST(MappedFile, WriteValuesMaxWritesEveryPieceAndReturnsTheLargest) {
  const fs::path dir = test::scratch_dir("mapped-pieces");
  const std::string path = (dir / "out.bin").string();
  for (unsigned threads : {1u, 3u}) {
    check_write_values_max<std::uint8_t>((std::int64_t{4} << 20) * 2 + 17, threads, path);
    check_write_values_max<std::uint16_t>((std::int64_t{2} << 20) * 3 + 5, threads, path);
    check_write_values_max<std::uint32_t>(1000, threads, path);
    check_write_values_max<std::uint64_t>((std::int64_t{1} << 19) + 1, threads, path);
    check_write_values_max<std::uint32_t>(0, threads, path);
  }
  fs::remove_all(dir);
}

TEST(MappedFile, ErrorsNameTheFile) {
  const fs::path dir = test::scratch_dir("mapped");
  try {
    MappedInput in((dir / "missing.npy").string());
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.npy"), std::string::npos) << e.what();
  }
  EXPECT_THROW(MappedInput(dir.string()), IoError); // a folder
  EXPECT_THROW(ReservedFile((dir / "no" / "such" / "x").string(), 10), IoError);
  fs::remove_all(dir);
}

// A disk too small is an error at construction, before any byte is written: simulated with a
// file-size limit (posix_fallocate fails with EFBIG, as with ENOSPC on a full disk), in a child
// process so the limit does not reach the other tests.
TEST(MappedFile, AnOutputThatDoesNotFitIsRefusedBeforeWriting) {
  const fs::path dir = test::scratch_dir("mapped");
  const std::string path = (dir / "big.bin").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit lim {};
    lim.rlim_cur = lim.rlim_max = 1 << 20;
    ::setrlimit(RLIMIT_FSIZE, &lim);
    int code = 1;
    try {
      ReservedFile out(path, std::uint64_t{64} << 20);
    } catch (const IoError& e) {
      code = std::strstr(e.what(), "does not fit on the disk") != nullptr ? 0 : 2;
    } catch (...) {
      code = 3;
    }
    ::_exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_FALSE(fs::exists(path)); // nothing half-written is left
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
