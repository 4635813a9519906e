// A scalar volume as read from a user's file: a 2D or 3D array of typed values (the dtype and
// the little-endian bytes as stored, so that a conversion can write them back bit for bit),
// placed in the lattice and in physical space.
//
//   array     dtype (bool, uint8..uint64, int8..int64, float32, float64), shape in C order
//             ((Z, Y, X) in 3D, (Y, X) in 2D: x fastest) and the raw bytes
//   lower     lattice coordinates of the first voxel (a .vol's Center keys, else 0): the
//             voxels are the Domain prod_k [lower_k, lower_k + shape_k - 1]
//   spacing   physical voxel size per axis (NIfTI pixdim, else 1), axis order of the shape
//   origin    physical centre of the first voxel: voxel p at origin_k + spacing_k (p_k -
//             lower_k) (NIfTI qoffset or sform translation; a NIfTI rotation is not kept)
//   slope, inter   physical value = slope * stored + inter in double (NIfTI scl_*; else 1, 0)
// Values are read exactly: value(i) is exact for every dtype but 64-bit integers past 2^53
// (use the bytes, or kernel/images/object_selection.hpp's exact comparisons, for those).
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/io/npy_io.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

struct ScalarVolume {
  NpyArray array;
  std::vector<std::int64_t> lower;
  std::vector<double> spacing;
  std::vector<double> origin;
  double slope = 1.0, inter = 0.0;

  int dim() const { return static_cast<int>(array.shape.size()); }
  std::int64_t count() const { return array.count(); }
  /// The lattice domain of the voxels (shape and lower bounds).
  Domain domain() const { return Domain(array.shape, lower); }
  /// True when the physical values differ from the stored ones (slope != 1 or inter != 0).
  bool scaled() const { return slope != 1.0 || inter != 0.0; }
  /// The physical value of voxel i (C order).
  double value(std::int64_t i) const;
  /// Checks the invariants (2 or 3 axes, extents >= 1, byte count, one lower, spacing and
  /// origin per axis, finite slope and inter); InvalidArgument naming the first violation.
  void validate() const;
};

/// The array as a volume at the origin of the lattice, spacing 1, origin 0, no scaling.
ScalarVolume make_scalar_volume(NpyArray array);

/// A 3D or 2D uint8 image as a volume (its lower bounds kept).
ScalarVolume make_scalar_volume(const Image<std::uint8_t>& image);

/// "(64, 64, 64) uint8" and the like, for messages.
std::string describe_volume(const ScalarVolume& v);

} // namespace zdg
