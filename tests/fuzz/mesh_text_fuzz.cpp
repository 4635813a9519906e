// Fuzz target: OBJ and OFF meshes (kernel/io/mesh_read.hpp), the input of `zdg voxelize`. A
// parsed mesh must be valid (PolygonMesh::validate); the first byte picks the format.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/mesh_read.hpp>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const zdg::PolygonMesh m = (data[0] & 1) ? zdg::parse_off_mesh(bytes, "fuzz.off")
                                             : zdg::parse_obj_mesh(bytes, "fuzz.obj");
    m.validate();
  } catch (const zdg::InvalidArgument&) {
    __builtin_trap(); // the parsers validate: an invalid mesh is a bug
  } catch (const zdg::Error&) {
  }
  return 0;
}
