#include <zdg/kernel/transforms/out_of_core_transform.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/mapped_file.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>

#include "tests/support/cli.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstring>
#include <filesystem>

namespace zdg {
namespace {

namespace fs = std::filesystem;

// A random 2-D or 3-D mask whose slices are wider than a page of values for some draws (so
// that the pass along axis 0 runs in several column blocks), a random metric, torus axes and
// mask item width.
struct OocCase {
  Domain dom;
  std::vector<std::uint8_t> mask; // items of `item` bytes
  int item = 1;
  TransformOptions opt;
};

OocCase random_ooc_case() {
  OocCase c;
  const int d = *rc::gen::inRange(2, 4);
  std::vector<std::int64_t> ext;
  ext.push_back(*rc::gen::inRange<std::int64_t>(1, 10));
  ext.push_back(*rc::gen::inRange<std::int64_t>(1, d == 2 ? 3000 : 50));
  if (d == 3) ext.push_back(*rc::gen::inRange<std::int64_t>(1, 70));
  c.dom = Domain(ext);
  c.item = *rc::gen::element(1, 2, 4, 8);
  const int density = *rc::gen::inRange(1, 100); // percent of background
  c.mask.assign(static_cast<std::size_t>(c.dom.size() * c.item), 0);
  const auto bits = *rc::gen::container<std::vector<std::uint32_t>>(
      static_cast<std::size_t>(c.dom.size()), rc::gen::arbitrary<std::uint32_t>());
  bool any_background = false;
  for (std::int64_t i = 0; i < c.dom.size(); ++i) {
    const bool background =
        bits[static_cast<std::size_t>(i)] % 100 < static_cast<unsigned>(density);
    any_background = any_background || background;
    if (!background) {
      c.mask[static_cast<std::size_t>(i * c.item + (bits[static_cast<std::size_t>(i)] >> 8) %
                                                       static_cast<std::uint32_t>(c.item))] = 1;
    }
  }
  if (!any_background) std::memset(c.mask.data(), 0, static_cast<std::size_t>(c.item));
  c.opt.metric = *rc::gen::element(Metric::l1(), Metric::l2(), Metric::linf(), Metric::lp(3));
  c.opt.torus.resize(static_cast<std::size_t>(d));
  for (int k = 0; k < d; ++k)
    c.opt.torus[static_cast<std::size_t>(k)] = *rc::gen::arbitrary<bool>();
  c.opt.threads = *rc::gen::inRange(1u, 4u);
  return c;
}

template <class T>
std::vector<T> in_memory(const OocCase& c) {
  std::vector<T> out(static_cast<std::size_t>(c.dom.size()));
  distance_transform_into<T>(c.dom, c.mask.data(), c.item, c.opt, out.data());
  return out;
}

// Theorem (separability): the pass along axis 0 commutes with cutting the other passes into
// slabs of slices and itself into blocks of columns, so the out-of-core values are those of the
// in-memory engine, to the bit; budgets from one slice to the whole volume.
TEST(OutOfCoreTransform, EqualsTheInMemoryTransform) {
  const fs::path dir = test::scratch_dir("ooc");
  test::check_property([&] {
    const auto c = random_ooc_case();
    const auto expect = in_memory<std::uint64_t>(c);
    const std::uint64_t slice = static_cast<std::uint64_t>(c.dom.stride(0));
    OutOfCoreOptions ooc;
    ooc.scratch_folder = dir.string();
    ooc.memory_budget =
        slice * static_cast<std::uint64_t>(c.item + 8) * *rc::gen::inRange<std::uint64_t>(1, 12);
    const std::uint64_t offset = *rc::gen::inRange<std::uint64_t>(0, 200);
    {
      ReservedFile file((dir / "out.bin").string(), offset + expect.size() * 8);
      const auto mx = distance_transform_out_of_core<std::uint64_t>(c.dom, c.mask.data(), c.item,
                                                                    c.opt, file, offset, ooc);
      std::vector<std::uint64_t> out(expect.size());
      file.read(offset, out.data(), out.size() * 8);
      RC_ASSERT(out == expect);
      RC_ASSERT(mx == *std::max_element(expect.begin(), expect.end()));
    }
    // A narrower output (the engine's values go through the scratch file).
    if (distance_transform_max_value(c.dom, c.opt) <= BigInt(65535)) {
      ReservedFile file((dir / "out.bin").string(), offset + expect.size() * 2);
      distance_transform_out_of_core<std::uint16_t>(c.dom, c.mask.data(), c.item, c.opt, file,
                                                    offset, ooc);
      std::vector<std::uint16_t> out16(expect.size());
      file.read(offset, out16.data(), out16.size() * 2);
      RC_ASSERT(std::equal(out16.begin(), out16.end(), expect.begin()));
    }
  });
  fs::remove(dir / "out.bin");
  EXPECT_TRUE(fs::is_empty(dir)); // the scratch files are gone
  fs::remove_all(dir);
}

// Regression (shrunk from a CI run under UBSan): l_3 on a 4 x 40 x 40 volume runs a 32-bit
// engine, and one block of all 1600 columns made the engine tabulate t^3 up to the block's
// width (1600^3 overflows 32 bits) although only axis 0 (extent 4) is transformed there.
TEST(OutOfCoreTransform, ColumnBlockWiderThanEveryExtent) {
  const fs::path dir = test::scratch_dir("ooc");
  Domain dom({4, 40, 40});
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(dom.size()), 1);
  mask[0] = 0;
  TransformOptions opt;
  opt.metric = Metric::lp(3);
  std::vector<std::uint64_t> expect(mask.size());
  distance_transform_into<std::uint64_t>(dom, mask.data(), 1, opt, expect.data());
  ReservedFile file((dir / "out.bin").string(), expect.size() * 8);
  OutOfCoreOptions ooc;
  ooc.scratch_folder = dir.string();
  ooc.memory_budget = 1 << 20; // one block of every column
  distance_transform_out_of_core<std::uint64_t>(dom, mask.data(), 1, opt, file, 0, ooc);
  std::vector<std::uint64_t> out(expect.size());
  file.read(0, out.data(), out.size() * 8);
  EXPECT_EQ(out, expect);
  fs::remove_all(dir);
}

// On a mapped mask whose pages are released after each slab (what `zdg transform dt
// --out-of-core` runs): the same values, read back from the file.
TEST(OutOfCoreTransform, MappedMaskWithReleasedPages) {
  const fs::path dir = test::scratch_dir("ooc");
  Domain dom({37, 61, 45});
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(dom.size()), 1);
  for (std::int64_t i = 0; i < dom.size(); i += 997) mask[static_cast<std::size_t>(i)] = 0;
  {
    ReservedFile m((dir / "mask.bin").string(), mask.size());
    m.write(0, mask.data(), mask.size());
    m.finish();
  }
  for (const Metric& metric : {Metric::l2(), Metric::l1()}) {
    TransformOptions opt;
    opt.metric = metric;
    opt.torus = {true, false, true};
    auto expect = distance_transform<std::uint32_t>(Image<std::uint8_t>(dom, mask), opt);
    MappedInput in((dir / "mask.bin").string());
    ReservedFile out((dir / "dt.bin").string(), mask.size() * 4);
    OutOfCoreOptions ooc;
    ooc.memory_budget = 61 * 45 * 5 * 3; // three slices of mask and values per slab
    ooc.mask_is_mapped_file = true;
    ooc.scratch_folder = dir.string();
    int slabs = 0, blocks = 0;
    ooc.progress = [&](const OutOfCoreProgress& p) { ++(p.phase == "slices" ? slabs : blocks); };
    distance_transform_out_of_core<std::uint32_t>(dom, in.data(), 1, opt, out, 0, ooc);
    EXPECT_EQ(slabs, 13);  // 37 slices, 3 per slab
    EXPECT_EQ(blocks, 10); // 2745 columns, 278 per block: budget / (37 x 4 bytes)
    std::vector<std::uint32_t> back(mask.size());
    out.read(0, back.data(), back.size() * 4);
    EXPECT_EQ(back, expect.values());
    out.finish();
  }
  fs::remove_all(dir);
}

TEST(OutOfCoreTransform, Errors) {
  const fs::path dir = test::scratch_dir("ooc");
  ReservedFile file((dir / "out.bin").string(), 1000);
  std::vector<std::uint8_t> line{0, 1, 1};
  EXPECT_THROW(
      distance_transform_out_of_core<std::uint32_t>(Domain({3}), line.data(), 1, {}, file, 0),
      InvalidArgument);
  std::vector<std::uint8_t> sq(100, 1);
  sq[5] = 0;
  OutOfCoreOptions tiny;
  tiny.memory_budget = 10; // one slice of 10 items needs 10 x (1 + 4) bytes
  try {
    distance_transform_out_of_core<std::uint32_t>(Domain({10, 10}), sq.data(), 1, {}, file, 0,
                                                  tiny);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("below one slice"), std::string::npos) << e.what();
  }
  std::vector<std::uint8_t> full(100, 1);
  EXPECT_THROW(
      distance_transform_out_of_core<std::uint32_t>(Domain({10, 10}), full.data(), 1, {}, file, 0),
      InvalidArgument);
  // uint8 output of an int32 engine needs a scratch folder
  EXPECT_THROW(
      distance_transform_out_of_core<std::uint8_t>(Domain({10, 10}), sq.data(), 1, {}, file, 0),
      InvalidArgument);
  file.finish();
  fs::remove_all(dir);
}

} // namespace
} // namespace zdg
