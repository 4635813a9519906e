// Fuzz target: the point cloud readers on the bytes of a file (kernel/io/point_cloud_io.hpp
// parse_point_cloud), the format chosen by the content as a user's extension would: "ply" ->
// PLY, the npy magic -> npy, "OFF" / "NOFF" -> OFF, anything else XYZ. A cloud it accepts is
// valid (validate_point_cloud passes again) and survives a write/read round trip of each
// writer's bytes, exactly.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/point_cloud_io.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace {

zdg::PointCloudFormat format_of(std::string_view b) {
  if (b.substr(0, 4) == "ply\n" || b.substr(0, 5) == "ply\r\n") return zdg::PointCloudFormat::ply;
  if (b.substr(0, 6) == "\x93NUMPY") return zdg::PointCloudFormat::npy;
  if (b.substr(0, 3) == "OFF" || b.substr(0, 4) == "NOFF") return zdg::PointCloudFormat::off;
  return zdg::PointCloudFormat::xyz;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  zdg::PointCloud c;
  try {
    c = zdg::parse_point_cloud(bytes, format_of(bytes), "fuzz.pts");
  } catch (const zdg::Error& e) {
    // One line, naming the file.
    const std::string_view m = e.what();
    if (m.find('\n') != std::string_view::npos || m.rfind("fuzz.pts", 0) != 0) __builtin_trap();
    return 0;
  }
  try {
    zdg::validate_point_cloud(c, "fuzz.pts");
  } catch (const zdg::Error&) {
    __builtin_trap(); // parse_point_cloud validated the cloud: an invalid one is a bug
  }
  if (c.size() > 10000) return 0;
  // The text of the cloud (%.17g: every double exactly) reads back to the same cloud.
  std::string text;
  for (std::size_t i = 0; i < c.size(); ++i) {
    char b[256];
    const auto& p = c.points[i];
    int n = std::snprintf(b, sizeof b, "%.17g %.17g %.17g", p.x, p.y, p.z);
    text.append(b, static_cast<std::size_t>(n));
    if (c.has_normals()) {
      const auto& v = c.normals[i];
      n = std::snprintf(b, sizeof b, " %.17g %.17g %.17g", v.x, v.y, v.z);
      text.append(b, static_cast<std::size_t>(n));
    }
    text += '\n';
  }
  try {
    const zdg::PointCloud back = zdg::parse_point_cloud(text, zdg::PointCloudFormat::xyz, "rt");
    if (back.points != c.points || back.normals != c.normals) __builtin_trap();
  } catch (const zdg::Error&) {
    __builtin_trap();
  }
  return 0;
}
