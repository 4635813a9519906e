#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>
#include <zdg/kernel/surfaces/pointel_cycles.hpp>

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

} // namespace zdg
