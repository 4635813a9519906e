// Reading input files whole: the content of regular files and pipes, and one clear IoError for
// a missing file, a folder, a device and a file over the limit.
#include <zdg/kernel/io/input_file.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/peak_memory.hpp"
#include <zdg/arith/error.hpp>

#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace zdg;

TEST(InputFile, ReadsRegularFilesWhole) {
  auto dir = test::scratch_dir("input");
  std::string bytes;
  for (int i = 0; i < 200000; ++i) bytes.push_back(static_cast<char>(i * 7919 % 256));
  std::ofstream(dir / "a.bin", std::ios::binary) << bytes;
  EXPECT_EQ(read_input_file((dir / "a.bin").string()), bytes);
  EXPECT_EQ(input_file_size((dir / "a.bin").string()), bytes.size());
  std::ofstream(dir / "empty.txt") << "";
  EXPECT_EQ(read_input_file((dir / "empty.txt").string()), "");
  std::filesystem::remove_all(dir);
}

TEST(InputFile, RefusesWhatIsNotAnInputFile) {
  auto dir = test::scratch_dir("input");
  std::ofstream(dir / "a.txt") << "0123456789";
  auto expect_error = [](const std::string& path, std::uint64_t limit, const std::string& msg) {
    try {
      read_input_file(path, limit);
      ADD_FAILURE() << path << " was read";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(msg), std::string::npos) << e.what();
    }
  };
  expect_error((dir / "missing").string(), kMaxInputFileBytes, "no such file");
  expect_error(dir.string(), kMaxInputFileBytes, "is a folder");
  expect_error("/dev/zero", kMaxInputFileBytes, "not a regular file");
  expect_error((dir / "a.txt").string(), 9, "larger than 9 bytes");
  EXPECT_THROW(input_file_size("/dev/null"), IoError);
  std::filesystem::remove_all(dir);
}

// The byte at position i of the test streams below.
std::uint8_t byte_at(std::uint64_t i) {
  return static_cast<std::uint8_t>(i * 131 % 251);
}

// Fills `bytes` with byte_at, in arrivals of at most `step` bytes.
void fill(ArrivingBytes& bytes, std::size_t step) {
  for (auto room = bytes.room(); !room.empty(); room = bytes.room()) {
    EXPECT_LE(room.size(), ArrivingBytes::kPiece);
    const std::size_t n = std::min(step, room.size());
    for (std::size_t i = 0; i < n; ++i) room[i] = byte_at(bytes.size() + i);
    bytes.arrived(n);
  }
}

TEST(InputFile, ArrivingBytesKeepsEveryByteInOrder) {
  const std::uint64_t claims[] = {0, 1, ArrivingBytes::kPiece - 1, ArrivingBytes::kPiece,
                                  5 * ArrivingBytes::kPiece / 2 + 7};
  for (const std::uint64_t claim : claims) {
    ArrivingBytes bytes(claim);
    fill(bytes, 1000003);
    EXPECT_EQ(bytes.size(), claim);
    EXPECT_TRUE(bytes.room().empty());
    const std::vector<std::uint8_t> all = bytes.take();
    ASSERT_EQ(all.size(), claim);
    for (std::uint64_t i = 0; i < claim; ++i) {
      if (all[i] != byte_at(i)) {
        ADD_FAILURE() << "claim " << claim << ": byte " << i << " differs";
        break;
      }
    }
  }
  // Fewer bytes than claimed (the caller's error to report): take() gives those that arrived.
  ArrivingBytes part(3 * ArrivingBytes::kPiece);
  auto room = part.room();
  for (std::size_t i = 0; i < 10; ++i) room[i] = byte_at(i);
  part.arrived(10);
  EXPECT_THROW(part.arrived(ArrivingBytes::kPiece), std::logic_error);
  EXPECT_EQ(part.take(), (std::vector<std::uint8_t>{byte_at(0), byte_at(1), byte_at(2), byte_at(3),
                                                    byte_at(4), byte_at(5), byte_at(6), byte_at(7),
                                                    byte_at(8), byte_at(9)}));
}

// Joining the pieces does not double the resident peak, also in a process whose allocator
// would keep freed 16 MiB blocks resident (a freed 30 MiB block raises glibc's threshold for
// mapping a block to 30 MiB, so 16 MiB heap blocks would follow): the peak of 96 MiB that
// arrive and are taken stays below 96 MiB plus two pieces.
TEST(InputFile, ArrivingBytesPeakIsTheBytesPlusOnePiece) {
  constexpr std::uint64_t kBytes = std::uint64_t{96} << 20;
  const auto run = test::run_in_child_measuring_memory([] {
    {
      std::vector<std::uint8_t> earlier(std::size_t{30} << 20, 1);
      if (earlier[12345] != 1) return std::string("?");
    }
    ArrivingBytes bytes(kBytes);
    for (auto room = bytes.room(); !room.empty(); room = bytes.room()) {
      std::memset(room.data(), 7, room.size());
      bytes.arrived(room.size());
    }
    const std::vector<std::uint8_t> all = bytes.take();
    const bool same = all.size() == kBytes && all.front() == 7 && all.back() == 7;
    return std::string(same ? "ok" : "wrong bytes");
  });
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.result, "ok");
  EXPECT_GE(run.growth_kib, static_cast<std::int64_t>(kBytes >> 10));
#if !defined(__SANITIZE_ADDRESS__)
  // (AddressSanitizer keeps freed blocks resident in its quarantine: the 30 MiB above stay.)
  EXPECT_LT(run.growth_kib, static_cast<std::int64_t>((kBytes + 2 * ArrivingBytes::kPiece) >> 10))
      << "KiB at the peak for " << (kBytes >> 20) << " MiB";
#endif
}

} // namespace
