#include <zdg/kernel/render/picture.hpp>

#include <zdg/arith/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A picture that does not compress (noise), of about 3 x 300 x 300 bytes.
zdg::RgbImage noise() {
  zdg::RgbImage img(300, 300, {0, 0, 0});
  std::uint32_t x = 12345;
  for (auto& b : img.rgb) {
    x = x * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(x >> 24);
  }
  return img;
}

// Issue #41, 11: a PNG that cannot be written (the file-size limit, ulimit -f, with SIGXFSZ
// ignored as the command line does) is one IoError naming the file and the system's reason;
// libpng prints nothing ("libpng error: Write Error" was a second stderr line).
TEST(Picture, AFailedPngWriteIsOneErrorAndPrintsNothing) {
  const fs::path dir = fs::temp_directory_path() / ("zdg_picture_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path png = dir / "p.png", err = dir / "stderr";
  const zdg::RgbImage img = noise();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || ::dup2(fd, 2) < 0) ::_exit(3);
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{8192, 8192};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(4);
    try {
      zdg::write_png(png.string(), img);
    } catch (const zdg::IoError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      std::fflush(stderr);
      ::_exit(0);
    }
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "no IoError";
  const std::string text = read(err);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_EQ(text, png.string() + ": PNG write failed (File too large)\n");
  EXPECT_FALSE(fs::exists(png));
  // The same picture without the limit is written whole.
  zdg::write_png(png.string(), img);
  EXPECT_EQ(read(png).substr(1, 3), "PNG");
  EXPECT_GT(fs::file_size(png), 8192u);
  fs::remove_all(dir);
}

} // namespace
