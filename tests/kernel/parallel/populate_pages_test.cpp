// assign_populated (kernel/parallel/populate_pages.hpp) is v.assign(n, value) whatever the mapping
// underneath: every element equal to value, for buffers below and above the 4 MiB threshold of
// the parallel mapping, any thread count, element types that are not trivially copyable, and a
// vector that already holds data; populate_pages never changes the contents of mapped memory.
#include <zdg/kernel/parallel/populate_pages.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace {

TEST(PopulatePages, AssignPopulatedIsAssign) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000},
                              (std::size_t{5} << 20) / sizeof(std::int64_t) + 7}) {
    for (const unsigned threads : {0u, 1u, 3u}) {
      std::vector<std::int64_t> v(3, 42); // a previous content, smaller capacity
      zdg::assign_populated<std::int64_t>(v, n, threads, -1);
      ASSERT_EQ(v.size(), n);
      EXPECT_TRUE(std::all_of(v.begin(), v.end(), [](std::int64_t x) { return x == -1; }));
      std::vector<double> d;
      zdg::assign_populated(d, n, threads);
      ASSERT_EQ(d.size(), n);
      EXPECT_TRUE(std::all_of(d.begin(), d.end(), [](double x) { return x == 0.0; }));
    }
  }
  std::vector<std::string> s{"a"};
  zdg::assign_populated(s, 5, 2, std::string("zdg"));
  EXPECT_EQ(s, std::vector<std::string>(5, "zdg"));
  std::vector<int> big(100000, 7); // enough capacity: assigned in place
  const int* where = big.data();
  zdg::assign_populated(big, 1000, 2, 9);
  EXPECT_EQ(big.data(), where);
  EXPECT_EQ(big, std::vector<int>(1000, 9));
}

TEST(PopulatePages, MappingKeepsTheContents) {
  std::vector<std::uint32_t> v((std::size_t{9} << 20) / 4);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::uint32_t(i * 2654435761u);
  zdg::populate_pages(v.data(), v.size() * 4, 2);
  zdg::populate_pages(nullptr, 1 << 30, 2);  // nothing to map
  zdg::populate_pages(v.data() + 1, 100, 0); // under the threshold: nothing
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], std::uint32_t(i * 2654435761u));
}

} // namespace
