// Symmetry of critical-kernel thinning under all 48 symmetries of the cube (8 of the square)
// on every random case (the fast test draws four symmetries per case).
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>

#include "tests/support/thinning_checks.hpp"
#include "tests/support/tower.hpp"

#include <gtest/gtest.h>

namespace zdg {
namespace {

TEST(CriticalKernelThinningSlow, InvariantUnderAllSymmetriesOfTheCube) {
  test::check_property([] {
    const int dim = *rc::gen::inRange(2, 4);
    const std::int64_t n = *rc::gen::inRange(3, dim == 3 ? 10 : 16);
    const auto img = test::random_cubic_image(dim, n);
    const SkeletonKind kinds[3] = {SkeletonKind::ultimate, SkeletonKind::curve,
                                   SkeletonKind::surface};
    ThinningOptions opt;
    opt.skeleton = kinds[*rc::gen::inRange(0, 3)];
    const auto ref = critical_kernel_thinning(img, opt).skeleton;
    for (const auto& s : test::symmetries(dim)) {
      const auto moved = critical_kernel_thinning(test::apply_symmetry(img, s), opt).skeleton;
      RC_ASSERT(test::apply_symmetry(moved, s, true) == ref);
    }
  });
}

} // namespace
} // namespace zdg
