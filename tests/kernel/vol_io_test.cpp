#include <zdg/kernel/vol_io.hpp>

#include "tests/support/cli.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace zdg {
namespace {

TEST(VolIo, RoundTripKeepsShapeAndLowerBound) {
  auto dir = test::scratch_dir("vol");
  Domain dom({2, 3, 4}, {-1, 0, 5});
  std::vector<std::uint64_t> v(24);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = i * 10;
  write_vol((dir / "a.vol").string(), Image<std::uint64_t>(dom, v));
  auto back = read_vol((dir / "a.vol").string());
  EXPECT_EQ(back.domain(), dom);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(back.values()[i], v[i]);
  v[0] = 256;
  EXPECT_THROW(write_vol((dir / "b.vol").string(), Image<std::uint64_t>(dom, v)), InvalidArgument);
  std::filesystem::remove_all(dir);
}

TEST(VolIo, DgtalHeaderAndErrors) {
  auto dir = test::scratch_dir("vol");
  std::string header = "X: 2\nY: 1\nZ: 1\nVoxel-Size: 1\nAlpha-Color: 0\nVoxel-Endian: 0\n"
                       "Int-Endian: 0123\nVersion: 2\n.\n";
  std::ofstream(dir / "a.vol", std::ios::binary) << header << "\x01\x02";
  auto img = read_vol((dir / "a.vol").string());
  EXPECT_EQ(img.domain().extents(), (std::vector<std::int64_t>{1, 1, 2}));
  EXPECT_EQ(img.values(), (std::vector<std::uint8_t>{1, 2}));
  std::ofstream(dir / "b.vol", std::ios::binary) << header << "\x01";
  EXPECT_THROW(read_vol((dir / "b.vol").string()), IoError); // truncated
  std::ofstream(dir / "c.vol", std::ios::binary) << "X: 2\nY: 1\nVersion: 3\n.\nxx";
  EXPECT_THROW(read_vol((dir / "c.vol").string()), IoError); // compressed / no Z
  std::ofstream(dir / "d.vol", std::ios::binary) << "X: 2\nY: 1\nZ: 1\n";
  EXPECT_THROW(read_vol((dir / "d.vol").string()), IoError); // no '.'
  std::ofstream(dir / "e.vol", std::ios::binary) << "X: two\nY: 1\nZ: 1\n.\nxx";
  EXPECT_THROW(read_vol((dir / "e.vol").string()), IoError);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
