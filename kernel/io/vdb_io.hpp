// OpenVDB volumes (.vdb) through the OpenVDB library (Debian's libopenvdb-dev; Museth,
// "VDB: High-resolution sparse volumes with dynamic topology", TOG 32(3), 2013), so that zdg
// exchanges sparse volumes with Houdini, Blender and the graphics tools.
//
// Reading: the first grid of the file whose value type is bool, float, double, int32 or int64
// (other grids, e.g. vec3, are skipped; none of these types is an IoError naming the types
// found). The dense array spans the box zdg wrote in the grid's metadata ("zdg_box_min",
// "zdg_box_max", when it holds the active voxels), else the bounding box of the active voxels
// (inactive ones read as the grid's background); its lower bounds are that box's minimum
// (index space), its spacing
// the voxel size and its origin the world position of the box's first voxel (OpenVDB puts voxel
// centres at integer index coordinates). A box past 2^32 voxels, a grid without an active voxel
// or a transform that is not an axis-aligned scale and translation is an IoError naming the file.
// dtypes: bool -> bool, float -> float32, double -> float64, int32 -> int32, int64 -> int64, or
// the integer dtype zdg named in the metadata ("zdg_dtype") when every value fits it.
// The array is (Z, Y, X) with x = the grid's first index coordinate.
//
// Writing (atomically, through the caller's staging path): one grid named "density", with the
// volume's box and integer dtype as metadata (so that a round trip gives the same array); the
// nonzero voxels are active, zero is the background. A bool volume, or an integer one whose values
// are 0 and 1, becomes a bool grid; float32 a float grid; float64 or a scaled volume a double grid
// (the physical values); other integers an int32 grid when they fit, else int64 (uint64 values past
// 2^63: InvalidArgument). A 2D image is written as one slice (z = 0); it reads back as a 3D volume
// of one slice, which the 2D commands take as 2D.
//
// When zdg is built without OpenVDB both calls throw IoError saying so.
#pragma once

#include <zdg/kernel/images/scalar_volume.hpp>

#include <string>

namespace zdg {

/// True when this build reads and writes .vdb files.
bool vdb_supported();

ScalarVolume read_vdb(const std::string& path);

void write_vdb(const std::string& path, const ScalarVolume& volume);

} // namespace zdg
