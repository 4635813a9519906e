#include <zdg/kernel/surfaces/marching_cubes.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>
#include <zdg/kernel/surfaces/pointel_cycles.hpp>

#include <algorithm>
#include <array>
#include <vector>

namespace zdg {

namespace {

// Triangles and centre vertices made for a polygon of n surfels.
constexpr std::int64_t triangles_of(int n) {
  return n == 3 ? 1 : (n == 4 ? 2 : n);
}

double squared_distance(const Point3<double>& a, const Point3<double>& b) {
  const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return dx * dx + dy * dy + dz * dz;
}

} // namespace

PolygonMesh marching_cubes(const Image<std::uint8_t>& image, const ImageSurfels& surfels,
                           const SurfaceConvention& convention, const VoxelPlacement& placement,
                           const IsoLevel* grey, unsigned threads) {
  const VoxelGrid& g = surfels.grid;
  const VoxelGrid ig = VoxelGrid::of(image.domain());
  if (ig.nx != g.nx || ig.ny != g.ny || ig.nz != g.nz)
    throw InvalidArgument("marching_cubes: the surfels are not those of this image");
  const std::uint8_t* data = image.values().data();
  const std::int64_t n = surfels.size();
  const PointelStar* stars = pointel_stars(convention.linels);
  PolygonMesh mesh;
  mesh.face_size = 3;

  const std::int64_t chunks = worker_count(threads, n);
  auto bounds = [&](std::int64_t t) {
    const std::int64_t q = n / chunks, r = n % chunks;
    return std::pair<std::int64_t, std::int64_t>{q * t + r * t / chunks,
                                                 q * (t + 1) + r * (t + 1) / chunks};
  };

  // Pass 1: the triangles and centres of the owned polygons, per chunk.
  std::vector<std::int64_t> first_triangle(static_cast<std::size_t>(chunks) + 1, 0),
      first_centre(static_cast<std::size_t>(chunks) + 1, 0);
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    std::int64_t tris = 0, centres = 0;
    for_each_surfel(surfels, b, e, [&](std::int64_t, std::uint64_t code, const std::int64_t* v) {
      for (int k = 0; k < 4; ++k) {
        const SurfelCorner sc = surfel_corner(v, code, k);
        const std::uint8_t config = pointel_configuration(g, data, sc.q[0], sc.q[1], sc.q[2]);
        const PointelStar& st = stars[config];
        if (st.owner[std::size_t(sc.face)] != sc.face) continue;
        const int len = st.length[std::size_t(sc.face)];
        tris += triangles_of(len);
        centres += len >= 5 ? 1 : 0;
      }
    });
    first_triangle[std::size_t(t) + 1] = tris;
    first_centre[std::size_t(t) + 1] = centres;
  });
  for (std::size_t t = 0; t < static_cast<std::size_t>(chunks); ++t) {
    first_triangle[t + 1] += first_triangle[t];
    first_centre[t + 1] += first_centre[t];
  }
  assign_populated(mesh.indices, static_cast<std::size_t>(3 * first_triangle.back()), threads);
  assign_populated(mesh.vertices, static_cast<std::size_t>(n + first_centre.back()), threads);

  // The surfel vertices: on the cut edge from the inner to the outer voxel centre.
  parallel_chunks(n, static_cast<unsigned>(chunks), [&](std::int64_t b, std::int64_t e) {
    for_each_surfel(surfels, b, e, [&](std::int64_t i, std::uint64_t code, const std::int64_t* c) {
      const std::int64_t v = code_voxel(code);
      const int a = code_axis(code);
      const int s = code_positive(code) ? 1 : -1;
      double step = 0.5;
      if (grey != nullptr) {
        std::int64_t w[3] = {c[0], c[1], c[2]};
        w[a] += s;
        if (w[a] >= 0 && w[a] < (a == 0 ? g.nx : (a == 1 ? g.ny : g.nz))) {
          const double fu = grey->value(v), fw = grey->value(g.index(w[0], w[1], w[2]));
          if (fu != fw) step = std::clamp((grey->level - fu) / (fw - fu), 0.0, 1.0);
        }
      }
      double p[3] = {double(c[0]), double(c[1]), double(c[2])};
      p[a] += s * step;
      mesh.vertices[std::size_t(i)] = placement.at(p[0], p[1], p[2]);
    });
  });

  // Pass 2: the polygons of the owned cycles, triangulated.
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    std::int64_t* out = mesh.indices.data() + 3 * first_triangle[std::size_t(t)];
    std::int64_t centre = n + first_centre[std::size_t(t)];
    std::array<std::int64_t, 12> poly{};
    auto emit = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      *out++ = x;
      *out++ = y;
      *out++ = z;
    };
    for_each_surfel(surfels, b, e, [&](std::int64_t i, std::uint64_t code, const std::int64_t* v) {
      for (int k = 0; k < 4; ++k) {
        const SurfelCorner sc = surfel_corner(v, code, k);
        const std::uint8_t config = pointel_configuration(g, data, sc.q[0], sc.q[1], sc.q[2]);
        const PointelStar& st = stars[config];
        if (st.owner[std::size_t(sc.face)] != sc.face) continue;
        const int len = st.length[std::size_t(sc.face)];
        int f = sc.face;
        for (int m = 0; m < len; ++m) {
          if (m == 0) {
            poly[0] = i;
          } else {
            const LocalSurfel ls = local_face_surfel(g, sc.q, f, config);
            poly[std::size_t(m)] = surfels.find_in_row(ls.row, ls.code);
            if (poly[std::size_t(m)] < 0)
              throw Error("marching_cubes: a surfel of a cycle is missing from the list");
          }
          f = st.next[std::size_t(f)];
        }
        const auto& P = mesh.vertices;
        if (len == 3) {
          emit(poly[0], poly[1], poly[2]);
        } else if (len == 4) {
          if (squared_distance(P[std::size_t(poly[0])], P[std::size_t(poly[2])]) <=
              squared_distance(P[std::size_t(poly[1])], P[std::size_t(poly[3])])) {
            emit(poly[0], poly[1], poly[2]);
            emit(poly[0], poly[2], poly[3]);
          } else {
            emit(poly[1], poly[2], poly[3]);
            emit(poly[1], poly[3], poly[0]);
          }
        } else {
          Point3<double> m{0, 0, 0};
          for (int j = 0; j < len; ++j) m = m + P[std::size_t(poly[std::size_t(j)])];
          const double inv = 1.0 / len;
          mesh.vertices[std::size_t(centre)] = {m.x * inv, m.y * inv, m.z * inv};
          for (int j = 0; j < len; ++j)
            emit(poly[std::size_t(j)], poly[std::size_t((j + 1) % len)], centre);
          ++centre;
        }
      }
    });
  });
  return mesh;
}

PolygonMesh marching_cubes(const VoxelPredicate& inside, const VoxelBox& b, double h,
                           unsigned threads) {
  check_voxel_box(b);
  const std::int64_t nx = b.hi.x - b.lo.x + 1, ny = b.hi.y - b.lo.y + 1, nz = b.hi.z - b.lo.z + 1;
  Image<std::uint8_t> mask(Domain({nz, ny, nx}, {b.lo.z, b.lo.y, b.lo.x}));
  auto& v = mask.values();
  for (std::int64_t z = 0, i = 0; z < nz; ++z)
    for (std::int64_t y = 0; y < ny; ++y)
      for (std::int64_t x = 0; x < nx; ++x, ++i)
        v[std::size_t(i)] = inside({b.lo.x + x, b.lo.y + y, b.lo.z + z}) ? 1 : 0;
  const VoxelPlacement place{{h, h, h},
                             {h * double(b.lo.x), h * double(b.lo.y), h * double(b.lo.z)}};
  return marching_cubes(mask, image_surfels(mask, threads), SurfaceConvention::of(6, 26), place,
                        nullptr, threads);
}

} // namespace zdg
