#include <zdg/kernel/io/pgm_io.hpp>

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

// Issue #18: a 32-byte PGM claiming width 2^40 asked for 2 TiB, a 21-byte one claiming
// 20000x20000 took 0.9 GB before saying "truncated". The raster the header announces is
// checked against the bytes present before the image is allocated (products checked against
// overflow), in P5 and in P2.
TEST(PgmIo, HeaderSizesAreCheckedBeforeAllocation) {
  auto expect_error = [](const std::string& bytes, const std::string& msg) {
    try {
      parse_pgm(bytes, "mem");
      ADD_FAILURE() << "accepted: " << bytes;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(msg), std::string::npos) << e.what();
    }
  };
  const std::string wide = "P5\n1099511627776 1\n255\nabcdefghi";
  EXPECT_EQ(wide.size(), 32u);
  expect_error(wide, "truncated pixel data: the header announces 1099511627776x1 pixels");
  const std::string square = "P5 20000 20000 255\nab";
  EXPECT_EQ(square.size(), 21u);
  expect_error(square, "20000x20000");
  expect_error("P2 20000 20000 255\n1 2 3", "ASCII");
  expect_error("P5 4294967296 4294967296 65535\n", "truncated pixel data");
  expect_error("P5 99999999999999999999 1 255\n", "width too large");
  expect_error("P5 2 1 255\n\x01", "truncated pixel data");
  // Numbers are decimal whatever their leading zeros.
  auto img = parse_pgm("P2 02 01 010\n09 010\n", "mem");
  EXPECT_EQ(img.domain().extent(1), 2);
  EXPECT_EQ(img.values(), (std::vector<std::uint16_t>{9, 10}));
}

} // namespace
} // namespace zdg
