// Fuzz target: PLY meshes (kernel/io/ply_read.hpp), the input of `zdg view`. A parsed mesh
// must be valid (every index in range, one value per face for each field) and the viewer page
// must be buildable from it.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/ply_read.hpp>
#include <zdg/kernel/render/mesh_html.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const zdg::PlyMesh p = zdg::parse_ply(bytes, "fuzz.ply");
    p.mesh.validate(); // throws InvalidArgument (a zdg::Error) on a broken invariant: trap
    for (const auto& [name, values] : p.vertex_scalars)
      if (static_cast<std::int64_t>(values.size()) != p.mesh.vertex_count()) __builtin_trap();
    if (p.mesh.face_count() < 100000) (void)zdg::mesh_html(p.mesh);
  } catch (const zdg::InvalidArgument&) {
    __builtin_trap(); // parse_ply validated the mesh: an invalid one is a bug
  } catch (const zdg::Error&) {
  }
  return 0;
}
