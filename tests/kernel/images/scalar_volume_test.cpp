#include <zdg/kernel/images/scalar_volume.hpp>

#include <gtest/gtest.h>

#include <cstring>

namespace zdg {
namespace {

TEST(ScalarVolume, ValuesDomainAndInvariants) {
  Image<std::uint8_t> img(Domain({2, 3, 4}, {-1, 0, 5}));
  for (std::int64_t i = 0; i < img.size(); ++i) img[i] = static_cast<std::uint8_t>(i);
  ScalarVolume v = make_scalar_volume(img);
  v.validate();
  EXPECT_EQ(v.dim(), 3);
  EXPECT_EQ(v.count(), 24);
  EXPECT_EQ(v.domain(), img.domain());
  EXPECT_EQ(v.spacing, (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(describe_volume(v), "(2, 3, 4) uint8");
  EXPECT_FALSE(v.scaled());
  EXPECT_EQ(v.value(7), 7.0);
  v.slope = 0.5;
  v.inter = 10;
  EXPECT_TRUE(v.scaled());
  EXPECT_EQ(v.value(7), 13.5);
  v.slope = 0;
  EXPECT_THROW(v.validate(), InvalidArgument);
  v.slope = 1;
  v.spacing.pop_back();
  EXPECT_THROW(v.validate(), InvalidArgument);
  v.spacing.push_back(1);
  v.array.bytes.pop_back();
  EXPECT_THROW(v.validate(), InvalidArgument);
  NpyArray a;
  a.shape = {5};
  a.bytes.resize(5);
  EXPECT_THROW(make_scalar_volume(a).validate(), InvalidArgument); // 1-D
  NpyArray f;
  f.dtype = DType::F32;
  f.shape = {1, 2};
  const float vals[2] = {-0.0f, 2.5f};
  f.bytes.resize(8);
  std::memcpy(f.bytes.data(), vals, 8);
  const ScalarVolume fv = make_scalar_volume(f);
  EXPECT_EQ(fv.value(1), 2.5);
  EXPECT_EQ(npy_to_mask(f).values(), (std::vector<std::uint8_t>{0, 1})); // -0.0 is zero
}

} // namespace
} // namespace zdg
