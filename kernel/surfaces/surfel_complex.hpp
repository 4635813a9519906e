// The cell complex of a digital surface for discrete calculus: surfels (2-cells), linels
// (1-cells) and pointels (0-cells) of a closed oriented quad surface, with their positions,
// areas, elementary normals and incidences (Grady-Polimeni, "Discrete Calculus", 2010;
// Desbrun-Kanso-Tong, "Discrete differential forms", 2008). Seen from the dual side, surfels
// are the dual vertices and each linel is the dual edge between its two surfels: functions on
// surfels are dual 0-forms, functions on linels dual 1-forms (the Laplace-Beltrami operators and
// the Ambrosio-Tortorelli functional of estimators/ live there).
//
//   pointels   the quad corners (positions in R^3)
//   surfels    the quads, counterclockwise seen from outside; centre = mean of the corners,
//              area and unit normal from the cross product of the diagonals (a unit square of
//              the grid of step h: area h^2, normal +-e_a exactly, the elementary normal)
//   linels     the sides of the quads: linel e joins the pointels (a, b), run a -> b by its
//              surfel face[0] and b -> a by face[1] (so d0 u (e) = u(face[1]) - u(face[0])
//              is the coboundary of a dual 0-form); its two surfels are adjacent (the
//              bel-adjacency of kernel/surfaces/digital_surface.hpp when the quads come from it)
//   surfel_linels[s][i]   the linel of side i of s (corner i -> corner i + 1)
//
// Built from the primal surface of kernel/surfaces/digital_surface.hpp (QuadSurface, Khalimsky
// corners, embedded at step h) or from a quad PolygonMesh (kernel/surfaces/primal_surface_mesh.hpp:
// one vertex per sheet at a pinched pointel). Sides are paired by sorting the directed sides
// (a, b) and (b, a); where a linel is pinched (four surfels share the pointel pair) the sides
// are paired in face order. A side without its reverse (a surface that is not closed) or
// unequal numbers of the two directions: InvalidArgument. O(F log F) time, O(F) memory;
// indices int64, positions double.
#pragma once

#include <zdg/arith/point.hpp>
#include <zdg/kernel/surfaces/digital_surface.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace zdg {

struct SurfelLinel {
  std::int64_t a = 0, b = 0;          ///< its pointels
  std::array<std::int64_t, 2> face{}; ///< face[0] runs a -> b, face[1] runs b -> a
};

struct SurfelComplex {
  std::vector<Point3<double>> pointels;
  std::vector<std::array<std::int64_t, 4>> surfels; ///< corner pointels, counterclockwise
  std::vector<Point3<double>> centres;              ///< per surfel
  std::vector<Point3<double>> normals;              ///< per surfel: unit elementary normal
  std::vector<double> areas;                        ///< per surfel
  std::vector<SurfelLinel> linels;
  std::vector<std::array<std::int64_t, 4>> surfel_linels; ///< side i: corner i -> i + 1

  std::int64_t surfel_count() const { return static_cast<std::int64_t>(surfels.size()); }
  std::int64_t linel_count() const { return static_cast<std::int64_t>(linels.size()); }
  std::int64_t pointel_count() const { return static_cast<std::int64_t>(pointels.size()); }
  /// The surfel across side i of surfel s.
  std::int64_t neighbour(std::int64_t s, int i) const {
    const auto& e = linels[static_cast<std::size_t>(
        surfel_linels[static_cast<std::size_t>(s)][static_cast<std::size_t>(i)])];
    return e.face[0] == s ? e.face[1] : e.face[0];
  }
};

/// The complex of the quads with corner positions `pointels` (any closed oriented quad mesh).
SurfelComplex surfel_complex(std::vector<Point3<double>> pointels,
                             std::vector<std::array<std::int64_t, 4>> quads);
/// The complex of a primal surface (kernel/surfaces/digital_surface.hpp) at grid step h, the
/// Khalimsky point k embedded at h (k - 1) / 2 + translation (kernel/surfaces/cubical_cells.hpp).
SurfelComplex surfel_complex(const QuadSurface& surface, double h,
                             Point3<double> translation = {0, 0, 0});
/// The complex of a quad mesh (face_size 4; InvalidArgument otherwise).
SurfelComplex surfel_complex(const PolygonMesh& mesh);

} // namespace zdg
