#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/surfaces/pointel_cycles.hpp>

#include "tests/support/binary_images.hpp"
#include "tests/support/mesh_checks.hpp"
#include "tests/support/tower.hpp"
#include "tests/support/volumes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace {

using zdg::SurfaceConvention;
using zdg::test::SmallVolume;

constexpr int kPairs[4][2] = {{6, 26}, {6, 18}, {18, 6}, {26, 6}};

std::int64_t voxels(const SmallVolume& v) {
  std::int64_t n = 0;
  for (auto b : v.data) n += b != 0;
  return n;
}

// Every boundary surface is a closed oriented 2-manifold: each edge in exactly two faces run
// in opposite directions, one fan around each vertex, except at the pinched linels
// (kernel/surfaces/pointel_cycles.hpp), the only edges seen in four faces (twice each way). Without
// them the mesh's components have the Euler characteristics of the surfaces of
// image_surfaces. In all cases V - E + F = sum of the surfaces' chi + pinched linels
// = 2 (b0 - b1 + b2) + 2 pinched pointels + pinched linels, with the Betti numbers of the
// brute-force homology of the object under the pair. The orientation is outward: the
// enclosed volume is the number of voxels.
TEST(PrimalSurfaceMesh, ClosedOrientedManifoldWithTheObjectsEuler) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(5);
    const auto img = zdg::test::to_image(v, 2, -1, 0);
    const auto sf = zdg::image_surfels(img, 1);
    for (const auto& p : kPairs) {
      const auto conv = SurfaceConvention::of(p[0], p[1]);
      const auto mesh =
          zdg::primal_surface_mesh(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), 1);
      mesh.validate();
      RC_ASSERT(mesh.face_count() == sf.size());
      const auto surfaces = zdg::image_surfaces(img, sf, conv, 1);
      std::int64_t quadruple = 0;
      const auto uses = zdg::test::edge_uses(mesh);
      for (const auto& [e, n] : uses) {
        RC_ASSERT(n.first == n.second);
        RC_ASSERT(n.first == 1 || n.first == 2);
        quadruple += n.first == 2;
      }
      RC_ASSERT(quadruple == surfaces.pinched_linels);
      const std::int64_t chi = mesh.vertex_count() - std::int64_t(uses.size()) + mesh.face_count();
      RC_ASSERT(chi == surfaces.euler_sum() + surfaces.pinched_linels);
      const auto b = zdg::test::object_betti(v, p[0], p[1]);
      RC_ASSERT(chi ==
                2 * (b[0] - b[1] + b[2]) + 2 * surfaces.pinched_pointels + surfaces.pinched_linels);
      if (surfaces.pinched_linels == 0) {
        RC_ASSERT(zdg::test::manifold_defect(mesh) == "");
        std::vector<std::int64_t> mine, theirs;
        for (const auto& c : zdg::test::mesh_components(mesh)) mine.push_back(c.euler());
        for (const auto& s : surfaces.surfaces) theirs.push_back(s.euler);
        std::sort(mine.begin(), mine.end());
        std::sort(theirs.begin(), theirs.end());
        RC_ASSERT(mine == theirs);
      }
      RC_ASSERT(std::abs(zdg::test::enclosed_volume(mesh) - double(voxels(v))) < 1e-9);
    }
  });
}

// Faces are the surfels in code order, their corners the surfel's pointels (placement: the
// lattice, then a scaled and shifted one).
TEST(PrimalSurfaceMesh, FacesAreTheSurfelsAtTheirPlace) {
  zdg::test::check_property([] {
    const SmallVolume v = *zdg::test::small_volume(4);
    const auto img = zdg::test::to_image(v, -3, 0, 5);
    const auto sf = zdg::image_surfels(img, 1);
    const auto conv = SurfaceConvention::of(26, 6);
    const zdg::VoxelPlacement scaled{{0.5, 2.0, 1.5}, {10, 20, 30}};
    const auto mesh =
        zdg::primal_surface_mesh(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), 2);
    const auto mesh2 = zdg::primal_surface_mesh(img, sf, conv, scaled, 2);
    RC_ASSERT(mesh.indices == mesh2.indices);
    for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
      const auto pts = zdg::surfel_pointels(sf.surfel(f));
      for (std::size_t c = 0; c < 4; ++c) {
        const auto& x = mesh.vertices[std::size_t(mesh.face(f)[c])];
        RC_ASSERT(x.x == 0.5 * double(pts[c].x - 1));
        RC_ASSERT(x.y == 0.5 * double(pts[c].y - 1));
        RC_ASSERT(x.z == 0.5 * double(pts[c].z - 1));
        const auto& y = mesh2.vertices[std::size_t(mesh2.face(f)[c])];
        RC_ASSERT(std::abs(y.x - (10 + 0.5 * (x.x + 3))) < 1e-12);
        RC_ASSERT(std::abs(y.y - (20 + 2.0 * x.y)) < 1e-12);
        RC_ASSERT(std::abs(y.z - (30 + 1.5 * (x.z - 5))) < 1e-12);
      }
    }
  });
}

TEST(PrimalSurfaceMesh, ThreadsDoNotChangeTheResult) {
  const auto img = zdg::test::ball_image(8, 50);
  const auto sf = zdg::image_surfels(img, 1);
  const auto conv = SurfaceConvention::of(6, 26);
  const auto a = zdg::primal_surface_mesh(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), 1);
  const auto b = zdg::primal_surface_mesh(img, sf, conv, zdg::VoxelPlacement::lattice(sf.grid), 3);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(zdg::test::mesh_components(a).at(0).euler(), 2);
}

// Two voxels along a linel: under (6,*) two cubes, the shared linel's two vertices doubled
// (8 + 8 vertices, a manifold); under (18,6) one sphere squeezed onto the linel: 14 vertices,
// and the linel is a pinched linel, in four quads.
TEST(PrimalSurfaceMesh, VerticesAreCopiedWhereSheetsTouch) {
  SmallVolume edge{2, 2, 1, {1, 0, 0, 1}};
  const auto img = zdg::test::to_image(edge);
  const auto sf = zdg::image_surfels(img);
  const auto lattice = zdg::VoxelPlacement::lattice(sf.grid);
  auto m = zdg::primal_surface_mesh(img, sf, SurfaceConvention::of(6, 26), lattice);
  EXPECT_EQ(m.vertex_count(), 16);
  EXPECT_EQ(zdg::test::mesh_components(m).size(), 2u);
  EXPECT_EQ(zdg::test::manifold_defect(m), "");
  m = zdg::primal_surface_mesh(img, sf, SurfaceConvention::of(18, 6), lattice);
  EXPECT_EQ(m.vertex_count(), 14);
  ASSERT_EQ(zdg::test::mesh_components(m).size(), 1u);
  const auto s = zdg::image_surfaces(img, sf, SurfaceConvention::of(18, 6));
  EXPECT_EQ(s.pinched_linels, 1);
  ASSERT_EQ(s.surfaces.size(), 1u);
  EXPECT_EQ(s.surfaces[0].euler, 2);
  // The background neck of a (6,26) object: a 3x3x3 block whose middle slice is two diagonal
  // voxels (the other two of its 2x2 centre are background, joined along the centre linel).
  auto block = zdg::test::volume_from_rows(2, {"##", "##", "#.", ".#", "##", "##"});
  const auto bimg = zdg::test::to_image(block);
  const auto bsf = zdg::image_surfels(bimg);
  const auto bs = zdg::image_surfaces(bimg, bsf, SurfaceConvention::of(6, 26));
  EXPECT_EQ(bs.pinched_linels, 1);
  EXPECT_EQ(bs.surfaces.size(), 1u);
}

// The interface mesh of a random labelled volume (#38 item 5): the faces between each pair of
// labels number that interface's surfels (label_interfaces), and for each label L the faces
// that hold it, oriented outward from L (as stored when L is the smaller label, reversed when it
// is the larger), are a closed oriented surface (each directed edge met as often as its
// reverse) enclosing exactly L's voxels (divergence theorem: sum of v0 . (v1 x v2) / 6 over the
// two triangles of each quad). Vertices are shared: one per pointel.
TEST(LabelInterfaceMesh, InterfacesAreClosedOrientedSurfacesOfEachLabel) {
  zdg::test::check_property([] {
    const std::int64_t nz = *rc::gen::inRange(1, 5), ny = *rc::gen::inRange(1, 5),
                       nx = *rc::gen::inRange(1, 5);
    const int nlabels = *rc::gen::inRange(1, 4);
    zdg::Image<std::int64_t> img{zdg::Domain({nz, ny, nx}, {-1, 2, 0})};
    for (auto& v : img.values()) v = *rc::gen::inRange(0, nlabels + 1) * 3;
    const zdg::VoxelPlacement placement{{1, 1, 1}, {0, 2, -1}};
    const zdg::PolygonMesh mesh = zdg::label_interface_mesh(img, 0, placement);
    RC_ASSERT(mesh.face_size == 4);
    const auto& la = mesh.face_scalars.at(0).second;
    const auto& lb = mesh.face_scalars.at(1).second;
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> counted;
    for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
      RC_ASSERT(la[std::size_t(f)] < lb[std::size_t(f)]);
      ++counted[{std::int64_t(la[std::size_t(f)]), std::int64_t(lb[std::size_t(f)])}];
    }
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> want;
    for (const auto& i : zdg::label_interfaces(img, 0)) want[{i.a, i.b}] = i.surfels;
    RC_ASSERT(counted == want);
    // Distinct vertex positions: one vertex per pointel.
    std::set<std::tuple<double, double, double>> pos;
    for (const auto& v : mesh.vertices) pos.insert({v.x, v.y, v.z});
    RC_ASSERT(pos.size() == mesh.vertices.size());
    std::set<std::int64_t> labels(img.values().begin(), img.values().end());
    for (const std::int64_t L : labels) {
      if (L == 0) continue;
      std::map<std::pair<std::int64_t, std::int64_t>, int> edges;
      double volume = 0;
      for (std::int64_t f = 0; f < mesh.face_count(); ++f) {
        const bool small = std::int64_t(la[std::size_t(f)]) == L;
        if (!small && std::int64_t(lb[std::size_t(f)]) != L) continue;
        auto c = mesh.face(f);
        std::int64_t q[4] = {c[0], c[1], c[2], c[3]};
        if (!small) std::reverse(q, q + 4);
        for (int k = 0; k < 4; ++k) {
          ++edges[{q[k], q[(k + 1) % 4]}];
          --edges[{q[(k + 1) % 4], q[k]}];
        }
        auto tri = [&](std::int64_t a, std::int64_t b, std::int64_t d) {
          const auto& p = mesh.vertices[std::size_t(a)];
          const auto& u = mesh.vertices[std::size_t(b)];
          const auto& w = mesh.vertices[std::size_t(d)];
          return (p.x * (u.y * w.z - u.z * w.y) - p.y * (u.x * w.z - u.z * w.x) +
                  p.z * (u.x * w.y - u.y * w.x)) /
                 6;
        };
        volume += tri(q[0], q[1], q[2]) + tri(q[0], q[2], q[3]);
      }
      for (const auto& [e, n] : edges) RC_ASSERT(n == 0);
      const auto voxels = std::count(img.values().begin(), img.values().end(), L);
      RC_ASSERT(std::abs(volume - double(voxels)) < 1e-9);
    }
  });
  // Labels past 2^24 would be rounded in a float property: refused.
  zdg::Image<std::int64_t> big{zdg::Domain({1, 1, 1}), std::int64_t{1} << 25};
  EXPECT_THROW(zdg::label_interface_mesh(big, 0, {}), zdg::InvalidArgument);
}

} // namespace
