// Estimators of the registry from the calculus on digital surfaces (#14): di-area, the digital
// integral of 1 with the surfel measure of the integral-invariant normal (estimators/
// digital_integration.hpp), compared with the shape's area in closed form; and the
// Laplace-Beltrami operators lb-heat (estimators/heat_laplace_beltrami.hpp), lb-cotan (primal
// surface), lb-cotan-mc (marching-cubes mesh) and lb-combinatorial
// (kernel/linalg/cotan_laplacian.hpp), lb-meanvalue and lb-idt (the primal surface split into
// triangles: kernel/linalg/mean_value_laplacian.hpp, intrinsic_delaunay.hpp), lb-polygonal and
// grad-polygonal (the corrected polygonal calculus, kernel/calculus/polygonal_calculus.hpp) applied
// to a test function u (the parameter `u`, convergence/scalar_field.hpp), compared at every element
// with Delta_S u at the nearest point of the true surface (its normal and principal curvatures from
// the shape's closed forms: exact for spheres, from the fundamental forms for the ellipsoid, torus
// and polynomial shapes). The
// regularized primal surface (estimators/surface_regularization.hpp, II normals, default
// energy): regularized-normal (each quad's normal against the true normal at the projection of
// its centroid) and regularized-area (the sum of the quads' areas against the shape's area).
#include <zdg/arith/error.hpp>
#include <zdg/convergence/digitized_3d.hpp>
#include <zdg/convergence/estimator.hpp>
#include <zdg/convergence/laplacian_comparison.hpp>
#include <zdg/convergence/scalar_field.hpp>
#include <zdg/estimators/digital_integration.hpp>
#include <zdg/estimators/heat_laplace_beltrami.hpp>
#include <zdg/estimators/ii_3d.hpp>
#include <zdg/estimators/surface_regularization.hpp>
#include <zdg/kernel/calculus/polygonal_calculus.hpp>
#include <zdg/kernel/linalg/cotan_laplacian.hpp>
#include <zdg/kernel/linalg/intrinsic_delaunay.hpp>
#include <zdg/kernel/linalg/mean_value_laplacian.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/surfel_complex.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace zdg {

namespace detail {

// DI_h(1) = sum over the boundary surfels of h^2 n_II(s) . n_elem(s), minus the area. The
// whole surface must be digitized: a box that clips the shape cuts the integral.
// The whole digitized surface (the calculus needs it closed): InvalidArgument when the box
// clips the shape.
Digitized3 whole_surface(const RunInput& in, const std::string& estimator) {
  Digitized3 d = digitize_3d(in);
  for (bool c : d.clipped) {
    if (c) {
      throw InvalidArgument(estimator + ": the box clips '" + in.shape.spec() + "': " + estimator +
                            " needs the whole, closed surface");
    }
  }
  return d;
}

// The surfel weights h^2 mu(s), mu = n_II . n_elem, II normal of radius R.
std::vector<double> ii_surfel_weights(const Digitized3& d, double h, double R) {
  const auto ii = ii_principal_curvatures(d.inside, d.box, d.surfels, h, R, 1);
  std::vector<Point3<double>> estimated, elementary;
  estimated.reserve(ii.size());
  elementary.reserve(ii.size());
  for (std::size_t i = 0; i < ii.size(); ++i) {
    estimated.push_back(ii[i].normal);
    const auto n = trivial_normal(d.surfels[i]);
    elementary.push_back({double(n.x), double(n.y), double(n.z)});
  }
  const auto mu = surfel_measure(estimated, elementary);
  const std::vector<double> areas(mu.size(), h * h);
  return surfel_weights(mu, areas);
}

} // namespace detail

namespace {

using detail::ii_surfel_weights;
using detail::whole_surface;

ErrorStats run_di_area(const RunInput& in) {
  const auto& shape = detail::as_3d(in.shape);
  const auto area = shape.area();
  if (!area) throw InvalidArgument("the area of '" + in.shape.spec() + "' is not known");
  const detail::Digitized3 d = whole_surface(in, "di-area");
  // di-area reads the radius law R = k h^alpha (alpha = 1/3 by default).
  const double R = in.k * std::pow(in.h, in.alpha);
  const auto w = ii_surfel_weights(d, in.h, R);
  const std::vector<double> one(w.size(), 1.0);
  ErrorAccumulator acc;
  acc.add(digital_integral(w, one) - *area);
  return acc.stats();
}

// The primal surface of the digitization regularized with the II normals (R = k h^alpha): the
// mesh (pointels, quads in the surfels' order) and the moved vertices.
struct Regularized {
  PolygonMesh mesh;
  std::vector<Point3<double>> positions;
};

Regularized regularized_surface(const RunInput& in, const std::string& estimator,
                                detail::Digitized3& d) {
  d = whole_surface(in, estimator);
  const double R = in.k * std::pow(in.h, in.alpha);
  const auto ii = ii_principal_curvatures(d.inside, d.box, d.surfels, in.h, R, 1);
  SurfelComplex cx = surfel_complex(primal_surface(d.surfels), in.h);
  Regularized out;
  out.mesh.face_size = 4;
  out.mesh.vertices = std::move(cx.pointels);
  out.mesh.indices.reserve(4 * cx.surfels.size());
  for (const auto& q : cx.surfels)
    out.mesh.indices.insert(out.mesh.indices.end(), q.begin(), q.end());
  std::vector<Point3<double>> normals;
  normals.reserve(ii.size());
  for (const auto& c : ii) normals.push_back(c.normal);
  RegularizationParameters p;
  p.threads = 1;
  out.positions = regularize_surface(out.mesh, normals, in.h, p).positions;
  return out;
}

ErrorStats run_regularized_normal(const RunInput& in) {
  detail::Digitized3 d;
  const Regularized r = regularized_surface(in, "regularized-normal", d);
  ErrorAccumulator acc;
  for (std::int64_t f = 0; f < r.mesh.face_count(); ++f) {
    const Point3<double> a = quad_vector_area(r.mesh, r.positions, f);
    Point3<double> c{0, 0, 0};
    for (auto v : r.mesh.face(f)) c += 0.25 * r.positions[std::size_t(v)];
    const SurfacePoint3 q = d.shape->project(c - d.t);
    const double cosine = dot(a, q.normal) / std::sqrt(dot(a, a) * dot(q.normal, q.normal));
    acc.add(std::acos(std::clamp(cosine, -1.0, 1.0)));
  }
  return acc.stats();
}

ErrorStats run_regularized_area(const RunInput& in) {
  const auto area = detail::as_3d(in.shape).area();
  if (!area) throw InvalidArgument("the area of '" + in.shape.spec() + "' is not known");
  detail::Digitized3 d;
  const Regularized r = regularized_surface(in, "regularized-area", d);
  double sum = 0;
  for (std::int64_t f = 0; f < r.mesh.face_count(); ++f) {
    const Point3<double> a = quad_vector_area(r.mesh, r.positions, f);
    sum += std::sqrt(dot(a, a));
  }
  ErrorAccumulator acc;
  acc.add(sum - *area);
  return acc.stats();
}

// u at points p of the world frame (the shape is X + t: u is a function of the shape's frame,
// so that the errors do not depend on the translation), and Delta_S u at the nearest point of
// the true surface.
struct TestFunction {
  ScalarField u;
  Point3<double> t;
  const Shape3* shape;
  double value(Point3<double> p) const { return u.value({p.x - t.x, p.y - t.y, p.z - t.z}); }
  double laplace_beltrami(Point3<double> p) const {
    const SurfacePoint3 q = shape->project({p.x - t.x, p.y - t.y, p.z - t.z});
    return u.laplace_beltrami(q.point, q.normal, q.k1, q.k2);
  }
};

TestFunction test_function(const RunInput& in, const detail::Digitized3& d) {
  if (in.function.empty()) throw InvalidArgument("no test function u given");
  return {ScalarField(in.function), d.t, d.shape};
}

// The errors L u (p_i) - Delta_S u (xi(p_i)) over the points p_i.
ErrorStats laplacian_errors(const TestFunction& f, std::span<const Point3<double>> points,
                            std::span<const double> lu) {
  ErrorAccumulator acc;
  for (std::size_t i = 0; i < points.size(); ++i) acc.add(lu[i] - f.laplace_beltrami(points[i]));
  return acc.stats();
}

std::vector<double> sampled(const TestFunction& f, std::span<const Point3<double>> points) {
  std::vector<double> u;
  u.reserve(points.size());
  for (const auto& p : points) u.push_back(f.value(p));
  return u;
}

// Heat-kernel LB on the surfel centres with the II surfel measure, t = h^alpha, truncated at
// 5 sqrt(2t).
ErrorStats run_lb_heat(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-heat");
  const TestFunction f = test_function(in, d);
  const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
  const auto w = ii_surfel_weights(d, in.h, in.k * std::cbrt(in.h));
  const HeatLaplaceBeltrami L(complex.centres, w, heat_kernel_time(in.h, in.alpha), 5.0, 1);
  return laplacian_errors(f, complex.centres, L.apply(sampled(f, complex.centres)));
}

// Cotangent LB M^{-1} S of the primal quads split into triangles, at the pointels.
ErrorStats run_lb_cotan(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-cotan");
  const TestFunction f = test_function(in, d);
  const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
  const auto triangles = triangulate_quads(complex.surfels);
  const CotanLaplacian L = cotan_laplacian(complex.pointels, triangles);
  return laplacian_errors(f, complex.pointels, L.apply(sampled(f, complex.pointels)));
}

// Mean-value LB D^{-1} W of the primal quads split into triangles, at the pointels (one copy
// per sheet at a pinched pointel: convergence/laplacian_comparison.hpp, sheet_triangles).
ErrorStats run_lb_meanvalue(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-meanvalue");
  const TestFunction f = test_function(in, d);
  const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
  const SheetTriangles m = sheet_triangles(complex);
  const MeanValueLaplacian L = mean_value_laplacian(m.vertices, m.triangles);
  return laplacian_errors(f, m.vertices, L.apply(sampled(f, m.vertices)));
}

// Intrinsic Delaunay LB of the primal quads split into triangles, at the pointels (one copy per
// sheet, as lb-meanvalue).
ErrorStats run_lb_idt(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-idt");
  const TestFunction f = test_function(in, d);
  const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
  const SheetTriangles m = sheet_triangles(complex);
  const CotanLaplacian L = intrinsic_delaunay_laplacian(m.vertices, m.triangles);
  return laplacian_errors(f, m.vertices, L.apply(sampled(f, m.vertices)));
}

// Cotangent LB of the marching-cubes mesh of the digitization (kernel/surfaces/marching_cubes.hpp,
// the (6,26) convention, level 1/2 between voxel centres), at its vertices.
ErrorStats run_lb_cotan_mc(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-cotan-mc");
  const TestFunction f = test_function(in, d);
  const PolygonMesh mesh = marching_cubes(d.inside, d.box, in.h, 1);
  const CotanLaplacian L = cotan_laplacian(mesh);
  return laplacian_errors(f, mesh.vertices, L.apply(sampled(f, mesh.vertices)));
}

// Combinatorial LB (1/area(s)) sum over the 4 neighbours (u(r) - u(s)), at the surfel centres.
ErrorStats run_lb_combinatorial(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-combinatorial");
  const TestFunction f = test_function(in, d);
  const SurfelComplex complex = surfel_complex(primal_surface(d.surfels), in.h);
  const SparseMatrix L = combinatorial_laplacian(complex);
  return laplacian_errors(f, complex.centres, L.multiply(sampled(f, complex.centres)));
}

// The primal quads and the II normals (radius k h^{1/3}) that re-embed them.
struct PolygonalSetup {
  SurfelComplex complex;
  PolygonMesh mesh;
  std::vector<Point3<double>> normals;
};

// The stabilization of the inner product of 1-forms (de Goes et al. 2020's value).
constexpr double kPolygonalLambda = 1.0;

PolygonalSetup polygonal_setup(const RunInput& in, const detail::Digitized3& d) {
  PolygonalSetup s{surfel_complex(primal_surface(d.surfels), in.h), {}, {}};
  s.mesh.face_size = 4;
  s.mesh.vertices = s.complex.pointels;
  for (const auto& q : s.complex.surfels)
    s.mesh.indices.insert(s.mesh.indices.end(), q.begin(), q.end());
  // The II normals in the order of d.surfels, which surfel_complex keeps.
  const auto ii =
      ii_principal_curvatures(d.inside, d.box, d.surfels, in.h, in.k * std::cbrt(in.h), 1);
  for (const auto& c : ii) s.normals.push_back(c.normal);
  return s;
}

// -M^{-1} L u at the pointels, L = D^T M D of the corrected polygonal calculus.
ErrorStats run_lb_polygonal(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "lb-polygonal");
  const TestFunction f = test_function(in, d);
  const PolygonalSetup s = polygonal_setup(in, d);
  const PolygonalCalculus calculus(s.mesh, s.normals);
  const auto lu = calculus.laplacian(kPolygonalLambda).multiply(sampled(f, s.complex.pointels));
  const auto m = calculus.vertex_masses();
  std::vector<double> delta(lu.size());
  for (std::size_t i = 0; i < lu.size(); ++i) delta[i] = -lu[i] / m[i];
  return laplacian_errors(f, s.complex.pointels, delta);
}

// |G u - grad_S u| per surfel, grad_S u the tangential gradient at the centre's nearest surface
// point.
ErrorStats run_grad_polygonal(const RunInput& in) {
  const detail::Digitized3 d = whole_surface(in, "grad-polygonal");
  const TestFunction f = test_function(in, d);
  const PolygonalSetup s = polygonal_setup(in, d);
  const PolygonalCalculus calculus(s.mesh, s.normals);
  const auto g = calculus.gradient().multiply(sampled(f, s.complex.pointels));
  ErrorAccumulator acc;
  for (std::size_t i = 0; i < s.complex.centres.size(); ++i) {
    const auto c = s.complex.centres[i];
    const SurfacePoint3 q = d.shape->project({c.x - d.t.x, c.y - d.t.y, c.z - d.t.z});
    const Jet3 j = f.u.jet(q.point);
    Point3<double> grad{j.gradient[0], j.gradient[1], j.gradient[2]};
    grad = grad - dot(grad, q.normal) * q.normal;
    const Point3<double> e{g[3 * i] - grad.x, g[3 * i + 1] - grad.y, g[3 * i + 2] - grad.z};
    acc.add(std::sqrt(dot(e, e)));
  }
  return acc.stats();
}

EstimatorParameter function_parameter() {
  EstimatorParameter p{"u", "x", 0, 0,
                       "test function u(x, y, z), e.g. x^2-y^2 (convergence/scalar_field.hpp)"};
  p.check_text = [](const std::string& text) {
    if (text.find(',') != std::string::npos) {
      throw InvalidArgument("function '" + text + "': no commas");
    }
    ScalarField{text};
  };
  return p;
}

} // namespace

namespace detail {

void register_calculus_estimators(std::vector<Estimator>& out) {
  out.push_back(
      {"di-area",
       3,
       "digital integral of 1: sum over the surfels of h^2 n_II . n_elem (II normal, R = k "
       "h^alpha), against the area in closed form",
       "area",
       radius_law_parameters(),
       {"O(h^{2/3}) with the II normal (R = k h^{1/3}) on C^3 surfaces with positive reach "
        "(Lachaud, Thibert, JMIV 2016: O(h) + O(normal error))",
        [](const ShapeClass& c, const EstimatorParameters& p) -> std::optional<ProvenRate> {
          if (c.c3 && is_one_third(p.alpha)) {
            return ProvenRate{2.0 / 3.0, "O(h^{2/3})",
                              "C^3 surface with positive reach, II normal with R = k h^{1/3}",
                              "Lachaud, Thibert, JMIV 2016; Coeurjolly, Lachaud, Levallois, "
                              "CVIU 2014"};
          }
          return std::nullopt;
        }},
       run_di_area});

  // The regularized surface: the paper reports convergence of its normals and area
  // experimentally; no rate is proven for them, so the fit is reported without a verdict.
  auto no_rate = [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
    return std::nullopt;
  };
  out.push_back({"regularized-normal",
                 3,
                 "normal of each quad of the primal surface regularized with the II normals (R "
                 "= k h^alpha; alpha 0.001, beta 1, gamma 0.05, each vertex in its pointel's "
                 "cube), against the true normal at the projection of the quad's centroid",
                 "angle (rad)",
                 radius_law_parameters(),
                 {"no rate proven (Coeurjolly, Gueth, Lachaud, TVCG 2021: convergence observed, "
                  "following the input II normals, O(h^{2/3}) at best)",
                  no_rate},
                 run_regularized_normal});
  out.push_back({"regularized-area",
                 3,
                 "total area of the regularized primal surface (quads' vector areas), against "
                 "the area in closed form",
                 "area",
                 radius_law_parameters(),
                 {"no rate proven (Coeurjolly, Gueth, Lachaud, TVCG 2021: convergence observed; "
                  "the staircase's own area does not converge)",
                  no_rate},
                 run_regularized_area});

  // lb-heat: k of the II normal's radius R = k h^{1/3}, alpha of t = h^alpha, u.
  EstimatorParameter heat_alpha{"alpha", "2/5", 0.0, 1.0,
                                "heat kernel time t = h^alpha, in (0, 1) (the theorem: alpha < "
                                "min(1/2, 2 beta / 3) = 4/9 with the II normal)"};
  heat_alpha.open_above = true;
  out.push_back(
      {"lb-heat",
       3,
       "heat-kernel Laplace-Beltrami operator on the surfel centres (Gaussian of time t = "
       "h^alpha, weights h^2 n_II . n_elem, II radius k h^{1/3}) applied to u, against Delta_S u "
       "at the nearest surface point",
       "Laplace-Beltrami",
       {{"k", "2", 0.0, 1e6, "radius factor of the II normal: R = k h^{1/3}"},
        heat_alpha,
        function_parameter()},
       {"converges uniformly for 0 < alpha < min(1/2, 2 beta/3) = 4/9 with the II normal "
        "(beta = 2/3) on C^3 surfaces (Caissard, Coeurjolly, Lachaud, Roussillon, JMIV 2019); "
        "no rate stated",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_heat});
  out.push_back(
      {"lb-cotan",
       3,
       "cotangent Laplacian M^{-1} S of the primal quad surface split into triangles (Pinkall, "
       "Polthier 1993) applied to u at the pointels, against Delta_S u at the nearest surface "
       "point",
       "Laplace-Beltrami",
       {function_parameter()},
       {"no convergence on digital surfaces: their normals do not converge (Hildebrandt, "
        "Polthier, Wardetzky 2006; Caissard et al., JMIV 2019, Table 1)",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_cotan});
  out.push_back(
      {"lb-cotan-mc",
       3,
       "cotangent Laplacian M^{-1} S of the marching-cubes mesh of the digitization ((6,26), "
       "level 1/2) applied to u at its vertices, against Delta_S u at the nearest surface point",
       "Laplace-Beltrami",
       {function_parameter()},
       {"no convergence proven: the marching-cubes vertices of a binary image are off the "
        "surface by O(h) and its normals do not converge (Caissard et al., JMIV 2019)",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_cotan_mc});
  out.push_back(
      {"lb-meanvalue",
       3,
       "mean-value Laplacian D^{-1} W (Floater 2003 weights (tan(a/2) + tan(b/2)) / |e|, D_i = "
       "sum_j w_ij |e_ij|^2 / 4) of the primal quad surface split into triangles, applied to u "
       "at the pointels, against Delta_S u at the nearest surface point",
       "Laplace-Beltrami",
       {function_parameter()},
       {"no convergence proven on surfaces (linear precision on planar meshes only: Floater "
        "2003; Wardetzky et al., SGP 2007); on a staircase, as the cotangent, it sees the O(h) "
        "offsets of the pointels divided by h^2",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_meanvalue});
  out.push_back(
      {"lb-idt",
       3,
       "cotangent Laplacian of the intrinsic Delaunay triangulation (Bobenko, Springborn 2007) "
       "of the primal quad surface split into triangles, applied to u at the pointels, against "
       "Delta_S u at the nearest surface point",
       "Laplace-Beltrami",
       {function_parameter()},
       {"no convergence on digital surfaces: the split quads are already intrinsically Delaunay "
        "(opposite angles of 45 or 90 degrees), so this is lb-cotan (Caissard et al., JMIV "
        "2019, Table 1, for the cotangent)",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_idt});
  out.push_back(
      {"lb-combinatorial",
       3,
       "combinatorial graph Laplacian of the surfel adjacency, (1/h^2) sum over the 4 "
       "neighbours (u(r) - u(s)), applied to u at the surfel centres, against Delta_S u at the "
       "nearest surface point",
       "Laplace-Beltrami",
       {function_parameter()},
       {"no convergence on surfaces that are not grid-aligned planes (Caissard et al., JMIV "
        "2019, Table 1)",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_combinatorial});
  out.push_back(
      {"lb-polygonal",
       3,
       "Laplacian -M^{-1} D^T M_1 D of the corrected polygonal calculus (de Goes, Butts, Desbrun "
       "2020, lambda = 1; the surfels re-embedded by the II normal of radius k h^{1/3}: "
       "Coeurjolly, Lachaud, DGMM 2022) applied to u at the pointels, against Delta_S u at the "
       "nearest surface point",
       "Laplace-Beltrami",
       {{"k", "1", 0.0, 1e6, "radius factor of the II normal: R = k h^{1/3}"},
        function_parameter()},
       {"no convergence proven; with u sampled at the pointels (the staircase) the re-embedded "
        "faces see an O(1) slope of u across them, and zdg measures no convergence on digital "
        "spheres, even with the true normals (Coeurjolly, Lachaud, DGMM 2022 report "
        "experiments only)",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_lb_polygonal});
  out.push_back(
      {"grad-polygonal",
       3,
       "per-surfel gradient G u of the corrected polygonal calculus against the tangential "
       "gradient of u at the centre's nearest surface point (the norm of the difference)",
       "gradient",
       {{"k", "1", 0.0, 1e6, "radius factor of the II normal: R = k h^{1/3}"},
        function_parameter()},
       {"consistent with converging normals (the gradient is exact on linear functions of a "
        "planar face; Coeurjolly, Lachaud, DGMM 2022); no rate proven",
        [](const ShapeClass&, const EstimatorParameters&) -> std::optional<ProvenRate> {
          return std::nullopt;
        }},
       run_grad_polygonal});
}

} // namespace detail

} // namespace zdg
