// The representative cycles of kernel/topology/homology_generators.hpp as an ASCII PLY file
// (PLY 1.0), for a viewer or a script:
//   element vertex   float x, y, z: the corners of the voxels that the cycles use, in lattice
//                    units (voxel p's closed cube is p +- 1/2; x is the last array axis, z the
//                    first: (X, Y, Z) of a (Z, Y, X) array; 2D: (X, Y, 0)), the image's lower
//                    bounds added
//   element point    int vertex, int cycle: the 0-cycles (one vertex per component)
//   element edge     int vertex1, vertex2, cycle: the edges of the 1-cycles
//   element face     list uchar int vertex_indices, int cycle: the squares of the 2-cycles (3D),
//                    counter-clockwise in their plane's axes
// Cycles are numbered 0, 1, ... through dimension 0, then 1, then 2; a comment line
// "betti b0 b1 [b2]" gives their counts. Errors: IoError when the file cannot be written.
#pragma once

#include <zdg/kernel/topology/homology_generators.hpp>

#include <string>
#include <vector>

namespace zdg {

/// Writes g to `path` (the caller stages it through an OutputSet); lower: the image's lower
/// bounds (one per axis).
void write_cycles_ply(const std::string& path, const HomologyGenerators& g,
                      const std::vector<std::int64_t>& lower);

} // namespace zdg
