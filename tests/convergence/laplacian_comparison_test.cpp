// The Laplacian comparison (Wardetzky, Mathur, Kalberer, Grinspun, SGP 2007) measured on a
// digital sphere and the faces of a rotated digital cube (convergence/laplacian_comparison):
// each measured property against what the operator's theory says on a staircase:
//   constants in the kernel of all seven;
//   symmetry of W L: all but the mean-value Laplacian (Floater's weights use the angles at i);
//   locality: the 1-ring operators couple elements at most a quad's diagonal apart (sqrt 2 h),
//     the heat kernel reaches 5 sqrt(2t) (t = h^{2/5}: 10.6 h at h = 0.2);
//   positive weights: the split quads are right isosceles triangles (cot 45 = 1, cot 90 = 0),
//     so cotan and idt have none negative, nor have the mean-value (tan(a/2) > 0), heat
//     (Gaussian) and combinatorial weights;
//   intrinsic Delaunay = cotangent on the staircase (already Delaunay: every row the same);
//   the sheet split of the surfels' quads: every edge in two triangles, V - E + F = 2.
// And the sweep's estimators lb-meanvalue and lb-idt through the driver: lb-idt's errors are
// lb-cotan's.
#include <zdg/arith/error.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/laplacian_comparison.hpp>
#include <zdg/convergence/shape.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace zdg {
namespace {

const std::vector<LaplacianProperties>& table() {
  static const auto rows = [] {
    LaplacianComparisonSettings s;
    s.h = 0.2;
    s.cube_half_side = 14;
    s.threads = 2;
    return measure_laplacian_properties(s);
  }();
  return rows;
}

const LaplacianProperties& row(const std::string& op) {
  for (const auto& r : table())
    if (r.op == op) return r;
  throw std::runtime_error("no row " + op);
}

TEST(LaplacianComparison, MeasuredPropertiesMatchTheTheory) {
  ASSERT_EQ(table().size(), laplacian_operator_names().size());
  for (const auto& r : table()) {
    SCOPED_TRACE(r.op);
    EXPECT_LT(r.constants, 1e-9);
    EXPECT_GT(r.linear_points, 0);
    EXPECT_GT(r.size, 400); // sphere1 at h = 0.2: 414 surfels, 416 pointels
    if (r.op == "meanvalue") {
      EXPECT_GT(r.asymmetry, 1e-3);
    } else {
      EXPECT_LT(r.asymmetry, 1e-12);
    }
    if (r.op == "heat") {
      EXPECT_GT(r.support_radius, 10); // 5 sqrt(2 h^0.4) / h = 10.6 at h = 0.2
      EXPECT_GT(r.mean_row_entries, 100);
    } else {
      EXPECT_LE(r.support_radius, std::sqrt(2.0) + 1e-9);
      EXPECT_LE(r.max_row_entries, 12);
    }
    if (r.op != "cotan-mc" && r.op != "polygonal") {
      EXPECT_EQ(r.negative_fraction, 0.0);
    }
  }
  EXPECT_EQ(row("combinatorial").max_row_entries, 4);
  // The staircase is intrinsically Delaunay: the idt row is the cotan row.
  const auto &c = row("cotan"), &d = row("idt");
  EXPECT_EQ(c.size, d.size);
  EXPECT_EQ(c.max_row_entries, d.max_row_entries);
  EXPECT_NEAR(c.mean_row_entries, d.mean_row_entries, 1e-12);
  EXPECT_NEAR(c.linear_defect, d.linear_defect, 1e-9);
  // No operator has linear precision on the staircase; the heat kernel comes closest.
  for (const auto& r : table())
    if (r.op != "heat") {
      EXPECT_GT(r.linear_defect, 10 * row("heat").linear_defect) << r.op;
    }
}

TEST(LaplacianComparison, SheetTrianglesAreAClosedManifold) {
  // Two voxels meeting along a linel (a pinched linel) and a 3x3x3 block: every edge in two
  // triangles run in opposite directions.
  for (int shape = 0; shape < 2; ++shape) {
    const VoxelPredicate inside = [shape](const Voxel& z) {
      if (shape == 0)
        return (z.x == 0 && z.y == 0 && z.z == 0) || (z.x == 1 && z.y == 1 && z.z == 0);
      return std::abs(z.x) <= 1 && std::abs(z.y) <= 1 && std::abs(z.z) <= 1;
    };
    const VoxelBox box{{-3, -3, -3}, {3, 3, 3}};
    const auto c = surfel_complex(primal_surface(boundary_surfels(inside, box)), 1.0);
    const SheetTriangles m = sheet_triangles(c);
    std::map<std::pair<std::int64_t, std::int64_t>, int> directed;
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k) ++directed[{t[std::size_t(k)], t[std::size_t((k + 1) % 3)]}];
    for (const auto& [e, n] : directed) {
      EXPECT_EQ(n, 1);
      EXPECT_EQ(directed.count({e.second, e.first}), 1u);
    }
    const auto V = std::int64_t(m.vertices.size()), E = std::int64_t(directed.size() / 2),
               F = std::int64_t(m.triangles.size());
    // The block: a sphere. The two voxels: the four quads at the pinched linel are paired in
    // face order (kernel/surfaces/surfel_complex.hpp), and the sheets follow that pairing.
    if (shape == 1) {
      EXPECT_EQ(V - E + F, 2);
      EXPECT_EQ(V, c.pointel_count());
    } else {
      EXPECT_EQ((V - E + F) % 2, 0);
      EXPECT_GE(V, c.pointel_count());
    }
  }
}

TEST(LaplacianComparison, IdtEstimatorIsCotanOnTheStaircase) {
  auto s = parse_shape("sphere1");
  const RunInput in{*s, 0.2, {0.01, -0.02, 0.03}, *s->bounding_box(), 0, 0, 0, "x^2-y^2"};
  const ErrorStats c = find_estimator("lb-cotan").run(in), d = find_estimator("lb-idt").run(in),
                   m = find_estimator("lb-meanvalue").run(in);
  EXPECT_EQ(c.n, d.n);
  EXPECT_NEAR(c.linf, d.linf, 1e-9 * c.linf);
  EXPECT_NEAR(c.mean, d.mean, 1e-9 * c.mean);
  EXPECT_EQ(m.n, c.n);
  EXPECT_GT(m.linf, 0);
}

TEST(LaplacianComparison, BadSettings) {
  const auto message = [](LaplacianComparisonSettings s) {
    try {
      measure_laplacian_properties(s);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  LaplacianComparisonSettings s;
  s.operators = {"nosuch"};
  EXPECT_NE(message(s).find("unknown operator 'nosuch'"), std::string::npos);
  s.operators = {"heat"};
  s.h = 0.2;
  s.cube_half_side = 8; // the heat kernel's 7.1 + 3 + 2 leaves nothing
  EXPECT_NE(message(s).find("take a larger cube"), std::string::npos);
  s.cube_half_side = 20;
  s.shape = "ball:3";
  EXPECT_NE(message(s).find("is not 3D"), std::string::npos);
  s.shape = "cylinder";
  s.h = 1;
  EXPECT_NE(message(s).find("the box clips"), std::string::npos);
  s.shape = "sphere1";
  s.h = 0;
  EXPECT_NE(message(s).find("h must be positive"), std::string::npos);
}

} // namespace
} // namespace zdg
