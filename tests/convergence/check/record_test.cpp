// Records of zdg check: the JSON text of the protocol, and shrink candidates that are simpler
// than their parent (so that greedy shrinking ends) and reach the small values.
#include <zdg/convergence/check/record.hpp>

#include "tests/support/tower.hpp"

#include <algorithm>

namespace {

using namespace zdg;
using namespace zdg::check;

TEST(CheckRecord, JsonTextOfTheProtocol) {
  Record r;
  r.integer("n", BigInt(5)).integer("m", BigInt(7)).integer("a", BigInt(-3));
  r.integer("b", BigInt(1) << 100);
  EXPECT_EQ(to_json(r),
            "{\"n\":\"5\",\"m\":\"7\",\"a\":\"-3\",\"b\":\"1267650600228229401496703205376\"}");
  Record p;
  p.array("points", {2, 2}, {BigInt(0), BigInt(0), BigInt(1), BigInt(-1)}, Shrink::path)
      .integer("connectivity", BigInt(8))
      .boolean("is_dss", true)
      .texts("factors", {"0", "a\"b"});
  EXPECT_EQ(to_json(p), "{\"points\":[[\"0\",\"0\"],[\"1\",\"-1\"]],\"connectivity\":\"8\","
                        "\"is_dss\":true,\"factors\":[\"0\",\"a\\\"b\"]}");
  Record img;
  img.array("image", {2, 3}, {BigInt(0), BigInt(1), BigInt(1), BigInt(1), BigInt(0), BigInt(1)},
            Shrink::image, true);
  EXPECT_EQ(to_json(img), "{\"image\":[[0,1,1],[1,0,1]]}");
  EXPECT_THROW(Record().array("x", {2, 2}, {BigInt(1)}), InvalidArgument);
}

// Every candidate is strictly simpler: fewer entries, or one value of smaller magnitude (or the
// same magnitude made nonnegative); and the first candidates are the smallest values.
TEST(CheckRecord, IntegerShrinksAreSimplerAndStartAtZero) {
  zdg::test::check_property([] {
    const BigInt v = BigInt(*rc::gen::arbitrary<std::int64_t>()) << *rc::gen::inRange(0, 80);
    const auto s = integer_shrinks(v);
    if (v == 0) {
      RC_ASSERT(s.empty());
      return;
    }
    RC_ASSERT(s.front() == 0);
    for (const auto& x : s) {
      RC_ASSERT(abs(x) < abs(v) || (abs(x) == abs(v) && x > 0 && v < 0));
    }
    // The last candidate is the neighbour towards 0: the binary search can end next to v.
    RC_ASSERT(s.back() == v - (v > 0 ? 1 : -1));
  });
}

TEST(CheckRecord, StructuralShrinksKeepShapesConsistent) {
  Record r;
  std::vector<BigInt> pts;
  for (int k = 0; k < 5; ++k) {
    pts.push_back(BigInt(100 + k));
    pts.push_back(BigInt(-7));
  }
  r.array("points", {5, 2}, pts, Shrink::path);
  r.array("image", {2, 3, 2}, std::vector<BigInt>(12, BigInt(1)), Shrink::image, true);
  const auto cands = shrink_candidates(r);
  ASSERT_FALSE(cands.empty());
  bool translated = false, cropped = false;
  for (const auto& c : cands) {
    const Field &p = c.at("points"), &im = c.at("image");
    EXPECT_EQ(p.ints.size(), shape_size(p.shape));
    EXPECT_EQ(im.ints.size(), shape_size(im.shape));
    EXPECT_LE(p.shape[0], 5u);
    EXPECT_FALSE(c == r);
    if (p.shape[0] == 5 && p.ints[0] == 0) {
      translated = true;
      // A translation keeps the steps of the path.
      for (std::size_t k = 1; k < 5; ++k) EXPECT_EQ(p.ints[2 * k] - p.ints[2 * k - 2], 1);
    }
    if (im.shape != std::vector<std::size_t>{2, 3, 2}) cropped = true;
  }
  EXPECT_TRUE(translated);
  EXPECT_TRUE(cropped);
}

} // namespace
