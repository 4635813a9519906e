// Reading input files whole: the content of regular files and pipes, and one clear IoError for
// a missing file, a folder, a device and a file over the limit.
#include <zdg/kernel/io/input_file.hpp>

#include "tests/support/cli.hpp"
#include <zdg/arith/error.hpp>

#include <fstream>
#include <string>

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

} // namespace
