// The lean distance transform of zdg transform dt (npy_distance_transform): the file it
// writes holds the in-memory transform's values (oracle: distance_transform on the image),
// in memory and out of core, in the narrowest unsigned dtype; what it does not take (float
// items) is left to the caller.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/npy_io.hpp>
#include <zdg/operations/transform_operations.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <filesystem>

namespace zdg {
namespace {

TEST(NpyDistanceTransform, FileEqualsTheInMemoryTransformInAndOutOfCore) {
  const auto dir = test::scratch_dir("npy_dt");
  int run = 0;
  test::check_property([&] {
    const std::vector<std::int64_t> shape = {*rc::gen::inRange<std::int64_t>(1, 6),
                                             *rc::gen::inRange<std::int64_t>(1, 7),
                                             *rc::gen::inRange<std::int64_t>(2, 9)};
    const std::int64_t n = shape[0] * shape[1] * shape[2];
    auto values =
        *rc::gen::container<std::vector<std::int64_t>>(std::size_t(n), rc::gen::inRange(0, 3));
    values[std::size_t(*rc::gen::inRange<std::int64_t>(0, n))] = 0; // a background point
    const auto dtype = *rc::gen::element(DType::U8, DType::I16, DType::I32, DType::Bool);
    if (dtype == DType::Bool)
      for (auto& v : values) v = v != 0 ? 1 : 0;
    const Metric metric =
        *rc::gen::element(Metric::l1(), Metric::l2(), Metric::linf(), Metric::lp(3));
    const auto in = (dir / ("in" + std::to_string(run) + ".npy")).string();
    const auto out = (dir / ("out" + std::to_string(run++) + ".npy")).string();
    write_npy(in, make_npy(dtype, shape, values));
    NpyTransformOptions o;
    o.input = in;
    o.output = out;
    o.transform.metric = metric;
    o.transform.threads = 1;
    o.out_of_core = *rc::gen::arbitrary<bool>();
    // in memory: through the output's mapped pages, a buffer and its write, or either
    o.shared_output = *rc::gen::element(std::optional<bool>{}, std::optional<bool>{true},
                                        std::optional<bool>{false});
    if (o.out_of_core) o.memory_budget = 4096; // tiny: many slabs
    const auto r = npy_distance_transform(o);
    RC_ASSERT(r.has_value());
    RC_ASSERT(r->out_of_core == o.out_of_core);
    const auto mask = npy_to_mask(read_npy(in));
    const auto dt = distance_transform<std::uint64_t>(mask, o.transform);
    const auto written = read_npy(out);
    RC_ASSERT(written.dtype ==
              *narrowest_unsigned(distance_transform_max_value(mask.domain(), o.transform)));
    const auto got = npy_to_int64(written);
    std::uint64_t mx = 0;
    for (std::int64_t i = 0; i < n; ++i) {
      RC_ASSERT(std::uint64_t(got[i]) == dt[i]);
      mx = std::max(mx, dt[i]);
    }
    RC_ASSERT(r->max_value == mx);
  });
  std::filesystem::remove_all(dir);
}

TEST(NpyDistanceTransform, FloatItemsAreLeftToTheGeneralPathUnlessOutOfCore) {
  const auto dir = test::scratch_dir("npy_dt_float");
  const auto in = (dir / "f.npy").string();
  write_npy(in, make_npy<double>({2, 3}, std::vector<double>{0, 1, 1, 1, -0.0, 1}));
  NpyTransformOptions o;
  o.input = in;
  o.output = (dir / "o.npy").string();
  EXPECT_FALSE(npy_distance_transform(o).has_value());
  EXPECT_FALSE(std::filesystem::exists(o.output));
  o.out_of_core = true;
  EXPECT_THROW(npy_distance_transform(o), InvalidArgument);
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace zdg
