#include <zdg/kernel/primal_surface_mesh.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel_for.hpp>
#include <zdg/kernel/pointel_cycles.hpp>

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
  const auto adj = convention.linels;
  PolygonMesh mesh;
  mesh.face_size = 4;
  mesh.indices.assign(static_cast<std::size_t>(4 * n), -1);

  const std::int64_t chunks = worker_count(threads, n);
  auto bounds = [&](std::int64_t t) {
    const std::int64_t q = n / chunks, r = n % chunks;
    return std::pair<std::int64_t, std::int64_t>{q * t + r * t / chunks,
                                                 q * (t + 1) + r * (t + 1) / chunks};
  };
  auto is_owner = [&](std::uint64_t code, int c, SurfelCorner& k) {
    k = surfel_corner(g, code, c);
    const std::uint8_t config = pointel_configuration(g, data, k.q[0], k.q[1], k.q[2]);
    const PointelStar& st = pointel_star(config, adj);
    return st.owner[std::size_t(k.face)] == k.face;
  };

  // Pass 1: owners per chunk.
  std::vector<std::int64_t> first_vertex(static_cast<std::size_t>(chunks) + 1, 0);
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    std::int64_t count = 0;
    SurfelCorner k{};
    for (std::int64_t i = b; i < e; ++i)
      for (int c = 0; c < 4; ++c) count += is_owner(surfels.codes[std::size_t(i)], c, k) ? 1 : 0;
    first_vertex[std::size_t(t) + 1] = count;
  });
  for (std::size_t t = 0; t < static_cast<std::size_t>(chunks); ++t)
    first_vertex[t + 1] += first_vertex[t];
  mesh.vertices.resize(static_cast<std::size_t>(first_vertex.back()));

  // Pass 2: the owners number their vertices and place them.
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    std::int64_t id = first_vertex[std::size_t(t)];
    SurfelCorner k{};
    for (std::int64_t i = b; i < e; ++i)
      for (int c = 0; c < 4; ++c) {
        if (!is_owner(surfels.codes[std::size_t(i)], c, k)) continue;
        mesh.vertices[std::size_t(id)] =
            placement.at(double(k.q[0]) - 0.5, double(k.q[1]) - 0.5, double(k.q[2]) - 0.5);
        mesh.indices[std::size_t(4 * i + c)] = id++;
      }
  });

  // Pass 3: the other corners take the vertex of their sheet's owner.
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t t) {
    const auto [b, e] = bounds(t);
    for (std::int64_t i = b; i < e; ++i) {
      const std::uint64_t code = surfels.codes[std::size_t(i)];
      for (int c = 0; c < 4; ++c) {
        auto& slot = mesh.indices[std::size_t(4 * i + c)];
        if (slot >= 0) continue;
        const SurfelCorner k = surfel_corner(g, code, c);
        const std::uint8_t config = pointel_configuration(g, data, k.q[0], k.q[1], k.q[2]);
        const PointelStar& st = pointel_star(config, adj);
        const std::uint64_t owner = local_face_code(g, k.q, st.owner[std::size_t(k.face)], config);
        const std::int64_t j = surfels.find(owner);
        if (j < 0) throw Error("primal_surface_mesh: the owner of a sheet is not a surfel");
        slot = mesh.indices[std::size_t(4 * j + corner_index(g, owner, k.q))];
        if (slot < 0) throw Error("primal_surface_mesh: the owner corner has no vertex");
      }
    }
  });
  return mesh;
}

} // namespace zdg
