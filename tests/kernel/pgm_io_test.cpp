#include <zdg/kernel/pgm_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace zdg {
namespace {

TEST(PgmIo, RoundTripAndAscii) {
  auto dir = test::scratch_dir("pgm");
  Image<std::uint64_t> img(Domain({2, 3}), std::vector<std::uint64_t>{0, 1, 2, 3, 4, 255});
  write_pgm((dir / "a.pgm").string(), img);
  auto back = read_pgm((dir / "a.pgm").string());
  EXPECT_EQ(back.domain().extents(), (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(back.values(), (std::vector<std::uint16_t>{0, 1, 2, 3, 4, 255}));
  img.values()[5] = 1000; // 16-bit
  write_pgm((dir / "b.pgm").string(), img);
  EXPECT_EQ(read_pgm((dir / "b.pgm").string()).values()[5], 1000);
  std::ofstream(dir / "c.pgm") << "P2\n# a comment\n3 1\n9\n1 0 9\n";
  EXPECT_EQ(read_pgm((dir / "c.pgm").string()).values(), (std::vector<std::uint16_t>{1, 0, 9}));
  img.values()[5] = 70000;
  EXPECT_THROW(write_pgm((dir / "d.pgm").string(), img), InvalidArgument);
  std::filesystem::remove_all(dir);
}

TEST(PgmIo, MalformedFilesNameTheLine) {
  auto dir = test::scratch_dir("pgm");
  std::ofstream(dir / "a.pgm") << "P2\n3 2\n9\n1 2 3\n4 x 6\n";
  try {
    read_pgm((dir / "a.pgm").string());
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(":5:"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "b.pgm", std::ios::binary) << "P5\n4 4\n255\nabc";
  EXPECT_THROW(read_pgm((dir / "b.pgm").string()), IoError); // truncated
  std::ofstream(dir / "c.pgm") << "P6\n1 1\n255\nabc";
  EXPECT_THROW(read_pgm((dir / "c.pgm").string()), IoError); // not PGM
  std::ofstream(dir / "d.pgm") << "";
  EXPECT_THROW(read_pgm((dir / "d.pgm").string()), IoError);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
