#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>
#include <zdg/kernel/surfaces/pointel_cycles.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <vector>

namespace zdg {

PolygonMesh primal_surface_mesh(const Image<std::uint8_t>& image, const ImageSurfels& surfels,
                                const SurfaceConvention& convention,
                                const VoxelPlacement& placement, unsigned threads) {
  const VoxelGrid& g = surfels.grid;
  const VoxelGrid ig = VoxelGrid::of(image.domain());
  if (ig.nx != g.nx || ig.ny != g.ny || ig.nz != g.nz)
    throw InvalidArgument("primal_surface_mesh: the surfels are not those of this image");
  const std::uint8_t* data = image.values().data();
  const std::int64_t n = surfels.size();
  const PointelStar* stars = pointel_stars(convention.linels);
  PolygonMesh mesh;
  mesh.face_size = 4;
  assign_populated<std::int64_t>(mesh.indices, static_cast<std::size_t>(4 * n), threads, -1);

  const std::int64_t chunks = worker_count(threads, n);
  auto bounds = [&](std::int64_t t) {
    const std::int64_t q = n / chunks, r = n % chunks;
    return std::pair<std::int64_t, std::int64_t>{q * t + r * t / chunks,
                                                 q * (t + 1) + r * (t + 1) / chunks};
  };
  // Pass 1: each corner is classified once. An owner's slot is marked -1; any other slot
  // records where its owner's slot is, as -2 - (4 j + corner of the owner j).
  std::vector<std::int64_t> first_vertex(static_cast<std::size_t>(chunks) + 1, 0);
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    std::int64_t owners = 0;
    for_each_surfel(surfels, b, e, [&](std::int64_t i, std::uint64_t code, const std::int64_t* v) {
      for (int c = 0; c < 4; ++c) {
        const SurfelCorner k = surfel_corner(v, code, c);
        const std::uint8_t config = pointel_configuration(g, data, k.q[0], k.q[1], k.q[2]);
        const PointelStar& st = stars[config];
        const int owner_face = st.owner[std::size_t(k.face)];
        auto& slot = mesh.indices[std::size_t(4 * i + c)];
        if (owner_face == k.face) {
          slot = -1;
          ++owners;
          continue;
        }
        const LocalSurfel owner = local_face_surfel(g, k.q, owner_face, config);
        const std::int64_t j = surfels.find_in_row(owner.row, owner.code);
        if (j < 0) throw Error("primal_surface_mesh: the owner of a sheet is not a surfel");
        slot = -2 - (4 * j + corner_index(owner.c, owner.code, k.q));
      }
    });
    first_vertex[std::size_t(t) + 1] = owners;
  });
  for (std::size_t t = 0; t < static_cast<std::size_t>(chunks); ++t)
    first_vertex[t + 1] += first_vertex[t];
  assign_populated(mesh.vertices, static_cast<std::size_t>(first_vertex.back()), threads);

  // Pass 2: the owners number their vertices (in surfel order) and place them.
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    std::int64_t id = first_vertex[std::size_t(t)];
    for_each_surfel(surfels, b, e, [&](std::int64_t i, std::uint64_t code, const std::int64_t* v) {
      for (int c = 0; c < 4; ++c) {
        auto& slot = mesh.indices[std::size_t(4 * i + c)];
        if (slot != -1) continue;
        const SurfelCorner k = surfel_corner(v, code, c);
        mesh.vertices[std::size_t(id)] =
            placement.at(double(k.q[0]) - 0.5, double(k.q[1]) - 0.5, double(k.q[2]) - 0.5);
        slot = id++;
      }
    });
  });

  // Pass 3: the other corners take their owner's vertex (owner slots are >= 0 by now and are
  // not written in this pass).
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    for (std::int64_t s = 4 * b; s < 4 * e; ++s) {
      auto& slot = mesh.indices[std::size_t(s)];
      if (slot <= -2) {
        const std::int64_t owner_slot = -2 - slot;
        slot = mesh.indices[std::size_t(owner_slot)];
      }
    }
  });
  return mesh;
}

PolygonMesh label_interface_mesh(const Image<std::int64_t>& labels, std::int64_t outside,
                                 const VoxelPlacement& placement) {
  if (labels.dim() != 3) {
    throw InvalidArgument("label interfaces: a " + std::to_string(labels.dim()) +
                          "-D image (the interface mesh is for 3D volumes)");
  }
  const Domain& d = labels.domain();
  const std::int64_t n[3] = {d.extent(2), d.extent(1), d.extent(0)}; // x, y, z
  const std::int64_t* v = labels.values().data();
  auto label = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
    if (x < 0 || y < 0 || z < 0 || x >= n[0] || y >= n[1] || z >= n[2]) return outside;
    return v[(z * n[1] + y) * n[0] + x];
  };
  const double limit = 16777216.0; // 2^24
  PolygonMesh mesh;
  mesh.face_size = 4;
  std::vector<double> la, lb;
  std::unordered_map<std::int64_t, std::int64_t> vertex; // pointel key -> index
  auto pointel = [&](std::int64_t qx, std::int64_t qy, std::int64_t qz) {
    const std::int64_t key = (qz * (n[1] + 1) + qy) * (n[0] + 1) + qx;
    const auto [it, fresh] = vertex.emplace(key, mesh.vertex_count());
    if (fresh) {
      mesh.vertices.push_back(placement.at(static_cast<double>(qx) - 0.5,
                                           static_cast<double>(qy) - 0.5,
                                           static_cast<double>(qz) - 0.5));
    }
    return it->second;
  };
  // Corners of the face between p and p + e_k, counterclockwise seen from +e_k: in the axes
  // (k+1, k+2) (cyclic), (0,0), (1,0), (1,1), (0,1).
  static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 3; ++k) {
    const int u = (k + 1) % 3, w = (k + 2) % 3;
    std::int64_t p[3];
    for (p[2] = k == 2 ? -1 : 0; p[2] < n[2]; ++p[2]) {
      for (p[1] = k == 1 ? -1 : 0; p[1] < n[1]; ++p[1]) {
        for (p[0] = k == 0 ? -1 : 0; p[0] < n[0]; ++p[0]) {
          const std::int64_t a = label(p[0], p[1], p[2]);
          const std::int64_t b = label(p[0] + (k == 0), p[1] + (k == 1), p[2] + (k == 2));
          if (a == b) continue;
          const std::int64_t lo = std::min(a, b), hi = std::max(a, b);
          if (static_cast<double>(hi) >= limit || static_cast<double>(lo) <= -limit) {
            throw InvalidArgument("label interfaces: label " +
                                  std::to_string(std::abs(lo) > hi ? lo : hi) +
                                  " is past 2^24 (the mesh stores labels as floats)");
          }
          // Seen from +e_k when the larger label is at p + e_k; else reversed.
          const bool forward = b > a;
          std::int64_t ids[4];
          for (int c = 0; c < 4; ++c) {
            std::int64_t q[3] = {p[0], p[1], p[2]};
            q[k] += 1;
            q[u] += corner[c][0];
            q[w] += corner[c][1];
            ids[c] = pointel(q[0], q[1], q[2]);
          }
          for (int c = 0; c < 4; ++c) mesh.indices.push_back(ids[forward ? c : 3 - c]);
          la.push_back(static_cast<double>(lo));
          lb.push_back(static_cast<double>(hi));
        }
      }
    }
  }
  mesh.face_scalars.emplace_back("label_a", std::move(la));
  mesh.face_scalars.emplace_back("label_b", std::move(lb));
  return mesh;
}

} // namespace zdg
