// The operations on the object of a user's image (zdg surface, zdg contour; the same
// operation `surface` of zdg serve and the Python function surface): options in, result out,
// one JSON form. The front ends read the image (cli/volume_input, the module's arrays), call,
// and write or print what the result holds.
//
//   surface_operation   3D: the object's components under the adjacency pair (all, or the
//                       K-th largest), its Betti numbers (kernel/topology/betti_numbers.hpp),
//                       the boundary surfels and their closed surfaces with Euler
//                       characteristic and genus (kernel/surfaces/image_surfaces.hpp), with
//                       harmonic the dimension of their harmonic 1-forms (exact ranks of d0
//                       and d1, O(S log S)), the
//                       estimates asked for (surface_estimators()), and a primal or
//                       marching-cubes mesh carrying them per face. O(N) for the image of N
//                       voxels plus the estimators' costs (integral invariants O(S R^3) for S
//                       surfels and a radius of R voxels; the calculus estimates one sparse
//                       solve on the S surfels). With `regularize`, the primal mesh's
//                       vertices are moved by estimators/surface_regularization.hpp with the
//                       II normals (each within the cube of side h of its pointel).
//   contour_operation   2D: components, Betti numbers, the contours (kernel/curves/
//                       image_contours.hpp) and the estimates asked for (contour_estimators()),
//                       O(N) plus the estimators'.
//
// Counts are exact (int64); estimates are doubles. Both take the mask by value and free what
// no later step reads (the grey values after the mesh, the mask after the mesh), so that the
// peak memory is that of the largest step.
//
// Errors (InvalidArgument, naming the image by ObjectImage::name): an adjacency pair that is
// not admissible in the dimension, a component rank above the number of components, an
// estimator name not in the registry, an estimate on anisotropic voxels, a radius larger than
// the image or than 256 voxels, a geodesic source that is not a surfel (index out of range,
// or a point more than two voxels from every surfel centre), and a geodesic estimate without
// a source (or a source without it), and regularize with a marching-cubes mesh.
#pragma once

#include <zdg/estimators/ambrosio_tortorelli.hpp>
#include <zdg/estimators/contour_estimators.hpp>
#include <zdg/estimators/surface_regularization.hpp>
#include <zdg/estimators/volume_ii.hpp>
#include <zdg/kernel/curves/image_contours.hpp>
#include <zdg/kernel/curves/marching_squares.hpp>
#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/images/scalar_volume.hpp>
#include <zdg/kernel/render/contour_svg.hpp>
#include <zdg/kernel/render/render_contours.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/mesh.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/operations/progress.hpp>

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace zdg {

// --- the estimator registry on user data ---------------------------------------------------

/// An estimator that zdg surface / zdg contour run on a user's image.
struct ImageEstimator {
  std::string name;    ///< as given to --estimate ("ii-mean")
  std::string summary; ///< one line for --help
};
/// In their output order (CSV columns, mesh fields): ii-mean, ii-gaussian, ii-k1, ii-k2,
/// ii-normal, ii-directions, geodesic, at-normal.
const std::vector<ImageEstimator>& surface_estimators();
/// ii-curvature, bc-tangent, lmst-tangent, mlp-length, gauss-area.
const std::vector<ImageEstimator>& contour_estimators();
/// The per-element scalar fields that can colour a picture, each with the estimator that
/// computes it: surface: ii-mean, ii-gaussian, ii-k1, ii-k2, geodesic, at-v (at-normal);
/// contour: ii-curvature.
const std::vector<std::pair<std::string, std::string>>& surface_color_fields();
const std::vector<std::pair<std::string, std::string>>& contour_color_fields();
/// "a, b, c": the names of a registry, for messages and help.
std::string estimator_names(const std::vector<ImageEstimator>& registry);
/// Checks `names` against the registry; InvalidArgument "--estimate: unknown estimator 'x'
/// (the list)" otherwise. Returns them as a set.
std::set<std::string> check_estimator_names(const std::vector<std::string>& names,
                                            const std::vector<ImageEstimator>& registry);

// --- the input -----------------------------------------------------------------------------

/// The object of an image and its physical embedding.
struct ObjectImage {
  Image<std::uint8_t> mask;            ///< nonzero = object; its domain is the lattice box
  std::vector<double> spacing, origin; ///< per axis in array order ((z, y, x) or (y, x))
  std::string name;                    ///< names the image in messages (its path)
  /// Marching cubes at a grey level: the values the mask was thresholded from, and the level
  /// (the positions are interpolated); empty: the mesh is on the binary mask.
  std::optional<ScalarVolume> grey;
  double grey_level = 0;
};

/// The integral-invariant radius: `value` in physical units, or in voxels when `voxels`.
struct EstimatorRadius {
  double value = 5;
  bool voxels = true;
  std::string text; ///< as the user gave it, for messages ("" = the default)
};

/// Parses "R" (physical units) or "Rv" (voxels or pixels, e.g. 5v); "" gives the default 5v.
/// InvalidArgument unless R is a positive finite number.
EstimatorRadius parse_estimator_radius(const std::string& text);

/// The grid step of an isotropic image (every spacing equal); InvalidArgument naming `name`
/// and the spacing otherwise.
double isotropic_step(const std::vector<double>& spacing, const std::string& name);

// --- zdg surface ---------------------------------------------------------------------------

/// The source of the geodesic estimate: a surfel index, or a physical point (the nearest
/// surfel centre, within two voxels).
struct GeodesicSource {
  std::optional<std::int64_t> surfel;
  Point3<double> point;
};

enum class SurfaceMesh { none, primal, marching_cubes };
const char* surface_mesh_name(SurfaceMesh m); // "primal", "marching-cubes" ("" for none)

/// The two discretizations of the Ambrosio-Tortorelli functional on a digital surface.
enum class ATDiscretization { linel, pointel };
const char* at_discretization_name(ATDiscretization d); // "linel", "pointel"

struct SurfaceOptions {
  AdjacencyPair adjacency{3, 6, 26};
  std::int64_t component = 0;         ///< 0: all; K >= 1: the K-th largest (1: the largest)
  std::vector<std::string> estimates; ///< names from surface_estimators()
  EstimatorRadius radius;
  /// The grid step h of the estimates; default: the spacing, which must then be isotropic.
  std::optional<double> step;
  std::optional<GeodesicSource> source; ///< for geodesic
  ATParameters at;                      ///< for at-normal
  /// Where at-normal's discontinuity function v lives: on the linels (estimators/
  /// ambrosio_tortorelli.hpp, the default) or on the pointels (estimators/
  /// ambrosio_tortorelli_mesh.hpp, the primal 0-form of the CGF 2016 paper).
  ATDiscretization at_v = ATDiscretization::linel;
  SurfaceMesh mesh = SurfaceMesh::none; ///< the mesh, with the estimates per face
  /// Regularize the primal mesh (it is then made even without an output) with the II normals
  /// (ii-normal is then estimated); a marching-cubes mesh is refused.
  std::optional<RegularizationParameters> regularize;
  bool keep_surfels = false; ///< the surfels and their surfaces stay in the result (for CSV)
  /// The dimension of the harmonic 1-forms of each closed surface, from the exact ranks of
  /// its exterior derivatives (kernel/calculus/harmonic_dimension.hpp; 2 genus, except on a
  /// surface through a pinched linel, whose primal complex may glue its passages crosswise).
  bool harmonic = false;
  unsigned threads = 0; ///< 0: all cores
  ProgressCallback progress;
};

/// Per selected component: its voxels and the totals of its boundary's surfaces.
struct SurfaceComponent {
  std::int64_t rank = 0, voxels = 0, surfels = 0, surfaces = 0, euler = 0, genus = 0;
  std::int64_t harmonic_dim = -1; ///< the sum over its surfaces (-1: not asked for)
};

/// The estimates per surfel (in the order of the sorted surfel codes).
struct SurfaceEstimates {
  std::set<std::string> names;
  double h = 1, R = 0; ///< the grid step and the radius in physical units
  std::vector<double> mean;
  std::vector<IIPrincipalCurvatures> principal;
  std::vector<double> geodesic; ///< NaN on the surfaces other than the source's
  std::int64_t source = -1;
  double geodesic_time = 0;
  std::string geodesic_solver;
  std::vector<Point3<double>> at_normal;
  std::vector<double> at_v; ///< the discontinuity field per surfel (minimum over its sides)
  ATParameters at;
  ATDiscretization at_discretization = ATDiscretization::linel;
  std::string at_solver;
  int at_iterations = 0;
};

struct SurfaceResult {
  AdjacencyPair adjacency;
  std::int64_t component = 0;
  std::int64_t object_components = 0;
  std::vector<SurfaceComponent> components; ///< the selected ones, by rank
  BettiNumbers betti;
  std::int64_t surfels = 0, surfaces = 0, pinched_pointels = 0, pinched_linels = 0;
  SurfaceEstimates estimates;
  SurfaceMesh mesh_kind = SurfaceMesh::none;
  std::optional<PolygonMesh> mesh; ///< with the estimates as face scalars and the normals
  std::int64_t mesh_edges = 0;
  /// With regularize: the parameters, energies and displacement (positions moved into mesh).
  std::optional<RegularizationParameters> regularization_parameters;
  std::optional<RegularizationResult> regularization;
  VoxelPlacement place;
  std::optional<ImageSurfels> surfels_kept; ///< keep_surfels
  std::vector<std::uint64_t> surface_of;    ///< keep_surfels: each surfel's surface
  unsigned threads = 1;                     ///< the worker count used
  std::map<std::string, double> seconds, cpu_seconds;
};

/// The checks that need no image (estimator names, the source with geodesic only): the front
/// ends call it before they read the input; surface_operation calls it too. Returns the
/// estimator names as a set.
std::set<std::string> check_surface_options(const SurfaceOptions& options);

SurfaceResult surface_operation(ObjectImage image, const SurfaceOptions& options);

/// {"adjacency","component","object_components","components":[{"rank","voxels","surfels",
/// "surfaces","euler","genus","harmonic_dim" (with
/// harmonic)}],"surfaces","surfels","euler","betti","pinched_pointels",
/// "pinched_linels","estimates":{...},"mesh":{"kind","vertices","faces","edges","euler"},
/// "regularization"?:{"alpha","beta","gamma","energy_before":{"data","alignment","fairness",
/// "total"},"energy_after":{...},"max_displacement_h","iterations","converged","solver"},
/// "seconds","cpu_seconds","threads"} (counts as decimal strings).
nlohmann::json to_json(const SurfaceResult& r);

/// One row per surfel: surfel, surface, its centre x, y, z (physical), its voxel, its
/// direction, then the estimates' columns. Needs keep_surfels. IoError when not written.
void write_surface_csv(const std::string& path, const SurfaceResult& r);

// --- zdg contour ---------------------------------------------------------------------------

struct ContourOptions {
  AdjacencyPair adjacency{2, 4, 8};
  std::int64_t component = 0;         ///< 0: all; K >= 1: the K-th largest
  std::vector<std::string> estimates; ///< names from contour_estimators()
  EstimatorRadius radius;
  /// Marching squares beside the linel contours (kernel/curves/marching_squares.hpp): on the
  /// image's grey values at its level when ObjectImage::grey is set, else the linel midpoints.
  bool interpolated = false;
  unsigned threads = 0;
  ProgressCallback progress;
};

struct ContourResult {
  AdjacencyPair adjacency;
  std::int64_t component = 0, object_components = 0;
  BettiNumbers betti;
  ImageContours contours;
  ContourEstimateRequest request;
  ContourEstimates estimates;
  std::vector<InterpolatedContour> interpolated; ///< one per contour, lattice coordinates
  bool interpolated_grey = false;                ///< on grey values (else linel midpoints)
  double interpolated_level = 0;
  double h = 1, R = 0;
  Image<std::uint8_t> mask; ///< the selected object (for a picture)
  Pixel origin_pixel;       ///< the lattice point at the physical origin
  Point2<double> origin;
  unsigned threads = 1;
  std::map<std::string, double> seconds, cpu_seconds;
};

ContourResult contour_operation(ObjectImage image, const ContourOptions& options);

/// {"adjacency","component","object_components","contours":[{"linels","pixels","kind",
/// "mlp-length"?,"interpolated"?:{"length","area"} (physical units)}],
/// "interpolated"?:{"level"|null,"length","area"},"linels","euler","betti","estimates":{...},"seconds","cpu_seconds",
/// "threads"}.
nlohmann::json to_json(const ContourResult& r);

/// One row per linel: contour, linel, pointel, Freeman code, midpoint (physical), inner
/// pixel, then the estimates' columns. IoError when not written.
void write_contour_csv(const std::string& path, const ContourResult& r);

/// The contours as an SVG drawing (kernel/render/contour_svg.hpp), coloured by ii-curvature
/// when estimated.
void write_contour_svg(const std::string& path, const ContourResult& r);

/// Each contour through its pointels and linel midpoints (lattice coordinates), with the
/// field's values when `field` is ii-curvature (a linel's at its midpoint, the mean of the two
/// linels' at a pointel), for render_contours_png.
std::vector<ContourPolyline> contour_polylines(const ContourResult& r, const std::string& field);

/// The contours as a flat mesh in the plane z = 0 for the viewer page (mesh_html with
/// top_view): each linel a quad ribbon along it, of width h / 3, counterclockwise seen from +z,
/// in physical coordinates (those of the CSV's midpoints). Per-face fields: "contour" (its
/// index), "ii-curvature" when estimated, and each tangent estimate's components at the linel's
/// start pointel ("bc-tangent x", "bc-tangent y", likewise lmst-tangent). O(linels).
PolygonMesh contour_mesh(const ContourResult& r);

// --- JSON helpers --------------------------------------------------------------------------

/// {"min","max","mean","count"} of the finite values ({"count":"0"} when none).
nlohmann::json value_stats(const std::vector<double>& values);

} // namespace zdg
