// Reading and writing point clouds (kernel/points/point_cloud.hpp): the input of `zdg normals`
// and of the reconstructions.
//
//   .ply  the vertex element's x, y, z (any PLY scalar type) and nx, ny, nz when all three are
//         there; a file without a face element is a point cloud, the faces of a mesh are
//         read, checked and ignored (kernel/io/ply_read.hpp's parser, parse_ply_points)
//   .xyz  text, one point a line: "x y z" or "x y z nx ny nz" (every line as the first), fields
//         separated by spaces or tabs; '#' starts a comment to the end of the line; blank
//         lines and "\r\n" line ends are accepted
//   .off  text: a first data line "OFF" (or "NOFF": each vertex line then carries its normal),
//         then "V F E" (the counts may follow the keyword on its line), then V vertex lines of
//         3 (6 for NOFF) numbers; what follows the vertices (the faces) is not read
//   .npy  a 2-D array N x 3 or N x 6 (the last three columns the normals), of any integer or
//         floating dtype (bool excepted), C or Fortran order (kernel/io/npy_io.hpp's parser)
//
// Numbers in text are read by std::from_chars (the nearest double: exact round trips of
// what write_point_cloud writes). Errors are IoError "SOURCE:LINE: what was wrong" for the
// text formats, "SOURCE: vertex R ..." / "SOURCE: row R ..." for PLY and npy (a non-finite
// value, a wrong field count, a malformed header, a count beyond what the file holds); then
// validate_point_cloud's InvalidArgument (no points, a zero normal, a point given twice,
// naming the points). Memory is taken as records are read, never for a header's count alone.
// Cost: O(size of the file) plus the O(N log N) validation.
//
// Writing: .ply binary little endian with double x, y, z (and double nx, ny, nz when the
// cloud has normals), no face element; .xyz with the shortest decimal text of each double
// (read back exactly); .npy float64 N x 3 or N x 6. The cloud is validated first; the file is
// written through a staging file and renamed (kernel/io/output_files.hpp): an error leaves
// nothing. .off is read, not written.
#pragma once

#include <zdg/kernel/points/point_cloud.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace zdg {

enum class PointCloudFormat { ply, xyz, off, npy };

/// The format of a file name by its extension (.ply, .xyz, .off, .npy, any case); IoError
/// naming the path otherwise.
PointCloudFormat point_cloud_format_of(const std::string& path);

/// The cloud in the bytes of a file of the given format; `source` names it in errors.
PointCloud parse_point_cloud(std::string_view bytes, PointCloudFormat format,
                             const std::string& source);

/// Reads the file at path in the format of its extension (kernel/io/input_file.hpp's checks).
PointCloud read_point_cloud(const std::string& path);

/// Writes .ply, .xyz or .npy, in `format` or that of the file name (give it when writing to
/// an OutputSet staging file). IoError for .off or another extension, InvalidArgument for a
/// cloud that validate_point_cloud refuses.
void write_point_cloud(const std::string& path, const PointCloud& cloud,
                       std::optional<PointCloudFormat> format = std::nullopt);

} // namespace zdg
