// The Python module zdg._zdg, part 2: numpy arrays in and out.
//
// Binary images: any numpy array; nonzero = object (foreground). A bool or integer array (1,
// 2, 4 or 8 bytes a value) that is C- or F-contiguous is read in place (no copy: a value is 0
// iff all its bytes are, whatever the byte order); any other one (floats, strided views) is
// first reduced to `a != 0` by numpy. The distance transform reads that buffer directly and writes
// into a numpy array it allocates (zero-copy in and out; an F-ordered input is the C-ordered image
// of the reversed axes, and the transform commutes with the permutation of axes, so its
// result is returned F-ordered). The Voronoi map and the reduced medial axis read such masks in
// place too (the library's Domain + pointer overloads; F order through the reversed axes, the
// site indices re-encoded), the reverse DT and the power map read C-contiguous int64 arrays in
// place (other integer arrays are converted once); the functions built on the library's
// Image<uint8_t> (components, Betti numbers, thinning, surfels, curvature, meshes) copy the
// mask once (1 byte a voxel). Results made by the library as vectors are handed to numpy
// without a copy (capsule-owned). Long computations run without the GIL.
#include "python/common.hpp"

#include <zdg/arith/error.hpp>
#include <zdg/estimators/volume_ii.hpp>
#include <zdg/kernel/images/voxel_dag.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/io/volume_io.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>
#include <zdg/kernel/render/mesh_html.hpp>
#include <zdg/kernel/surfaces/image_surfaces.hpp>
#include <zdg/kernel/surfaces/image_surfels.hpp>
#include <zdg/kernel/surfaces/marching_cubes.hpp>
#include <zdg/kernel/surfaces/primal_surface_mesh.hpp>
#include <zdg/kernel/topology/adjacency.hpp>
#include <zdg/kernel/topology/betti_numbers.hpp>
#include <zdg/kernel/topology/connected_components.hpp>
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>
#include <zdg/kernel/topology/homotopic_thinning.hpp>
#include <zdg/kernel/topology/simple_points.hpp>
#include <zdg/kernel/topology/skeleton_constraints.hpp>
#include <zdg/kernel/transforms/chamfer_transform.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/local_thickness.hpp>
#include <zdg/kernel/transforms/power_map.hpp>
#include <zdg/kernel/transforms/reduced_medial_axis.hpp>
#include <zdg/kernel/transforms/reverse_distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>
#include <zdg/kernel/transforms/voronoi_map.hpp>
#include <zdg/operations/reconstruct_operations.hpp>
#include <zdg/operations/surface_operations.hpp>

#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace zdg::python {

namespace {

/// A binary image seen in place: `data` holds one byte a point (nonzero = object) in C order
/// of `shape`; `fortran`: the array is F-ordered and `shape` is its reversed shape.
struct MaskView {
  const std::uint8_t* data = nullptr;
  int item = 1; // bytes per point (1, 2, 4 or 8): a point is background when all are 0
  std::vector<std::int64_t> shape;
  bool fortran = false;
  py::array keep; // the array that owns `data`
  std::int64_t size() const {
    std::int64_t n = 1;
    for (auto e : shape) n *= e;
    return n;
  }
  /// Point i is object (some byte nonzero).
  bool object(std::int64_t i) const {
    const std::uint8_t* p = data + i * item;
    for (int b = 0; b < item; ++b) {
      if (p[b] != 0) return true;
    }
    return false;
  }
};

/// A bool or integer dtype of 1, 2, 4 or 8 bytes: read in place, whatever its byte order (a
/// value is 0 iff all its bytes are).
bool integral_in_place(const py::array& a) {
  const char kind = a.dtype().kind();
  const auto s = a.itemsize();
  return (kind == 'b' || kind == 'i' || kind == 'u') && (s == 1 || s == 2 || s == 4 || s == 8);
}

MaskView mask_view(const py::object& obj, bool allow_fortran, const char* what) {
  py::array a = py::array::ensure(obj);
  if (!a) throw py::type_error(std::string(what) + ": expected a numpy array");
  if (a.ndim() == 0) throw InvalidArgument(std::string(what) + ": a 0-dimensional array");
  if (a.size() == 0) throw InvalidArgument(std::string(what) + ": an empty array");
  bool c = (a.flags() & py::array::c_style) != 0, f = (a.flags() & py::array::f_style) != 0;
  if (!integral_in_place(a) || !(c || (allow_fortran && f))) {
    py::module_ np = py::module_::import("numpy");
    py::array nz = np.attr("not_equal")(a, 0);
    a = np.attr("ascontiguousarray")(nz);
    c = true;
  }
  MaskView v;
  v.keep = a;
  v.data = static_cast<const std::uint8_t*>(a.data());
  v.item = static_cast<int>(a.itemsize());
  v.fortran = !c;
  for (py::ssize_t k = 0; k < a.ndim(); ++k) v.shape.push_back(a.shape(k));
  if (v.fortran) std::reverse(v.shape.begin(), v.shape.end());
  return v;
}

/// The library's image of a mask (values 0 / 1, C order).
Image<std::uint8_t> image_of(const py::object& obj, const char* what) {
  MaskView v = mask_view(obj, false, what);
  Image<std::uint8_t> img{Domain(v.shape)};
  std::uint8_t* out = img.values().data();
  const std::int64_t n = img.size();
  py::gil_scoped_release release;
  for (std::int64_t i = 0; i < n; ++i) out[i] = v.object(i) ? 1 : 0;
  return img;
}

std::vector<std::int64_t> shape_of(const MaskView& v) {
  std::vector<std::int64_t> s = v.shape;
  if (v.fortran) std::reverse(s.begin(), s.end());
  return s;
}

// Metric, torus flags (one bool, or one per axis) and threads of a transform call.
TransformOptions transform_options(const std::string& metric, const py::object& torus,
                                   unsigned threads, std::size_t d) {
  TransformOptions opt;
  opt.metric = parse_metric(metric);
  opt.threads = threads;
  if (!torus.is_none()) {
    if (py::isinstance<py::bool_>(torus)) {
      opt.torus.assign(d, torus.cast<bool>());
    } else {
      for (py::handle t : py::iter(torus)) opt.torus.push_back(t.cast<bool>());
      if (!opt.torus.empty() && opt.torus.size() != d) {
        throw InvalidArgument("torus has " + std::to_string(opt.torus.size()) + " flags for a " +
                              std::to_string(d) + "-dimensional array");
      }
    }
  }
  return opt;
}

// --- distance transform ---------------------------------------------------------------------

template <class V>
py::array engine_array(const MaskView& in, const Domain& dom, const TransformOptions& opt,
                       const detail::EnvelopeBounds& bounds) {
  std::vector<py::ssize_t> shape;
  for (auto e : shape_of(in)) shape.push_back(e);
  py::array_t<V> out = in.fortran ? py::array_t<V>(py::array_t<V, py::array::f_style>(shape))
                                  : py::array_t<V>(shape);
  V* f = out.mutable_data();
  {
    py::gil_scoped_release release;
    // numpy's fresh buffer, mapped (huge pages where offered) by the workers before the passes
    populate_pages(f, static_cast<std::size_t>(dom.size()) * sizeof(V),
                   detail::resolve_threads(opt.threads, dom.size()));
    V inf = detail::envelope_infinity<V>(bounds);
    detail::separable_envelope<V>(dom, opt, in.data, f, inf, nullptr, in.item);
  }
  return out;
}

py::array distance_transform_py(const py::object& obj, const std::string& metric,
                                const py::object& torus, unsigned threads) {
  MaskView in = mask_view(obj, true, "distance_transform");
  TransformOptions opt = transform_options(metric, torus, threads, in.shape.size());
  // An F-ordered input is the C-ordered image of the reversed axes.
  if (in.fortran) std::reverse(opt.torus.begin(), opt.torus.end());
  Domain dom(in.shape);
  auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  require_background(dom, in.data, opt, in.item);
  switch (bounds.width) {
  case detail::ValueWidth::I32:
    return engine_array<std::int32_t>(in, dom, opt, bounds);
  case detail::ValueWidth::I64:
    return engine_array<std::int64_t>(in, dom, opt, bounds);
  default:
    break;
  }
  // Values beyond 64 bits (large p): exact Python ints in an object array.
  Image<std::uint8_t> img{dom};
  for (std::int64_t i = 0; i < in.size(); ++i) img.values()[std::size_t(i)] = in.object(i) ? 1 : 0;
  Image<BigInt> big = [&] {
    py::gil_scoped_release release;
    return distance_transform<BigInt>(img, opt);
  }();
  py::module_ np = py::module_::import("numpy");
  py::array out = np.attr("empty")(shape_of(in), py::arg("dtype") = "object",
                                   py::arg("order") = in.fortran ? "F" : "C");
  auto** cells = static_cast<PyObject**>(out.mutable_data());
  for (std::int64_t i = 0; i < big.size(); ++i) {
    PyObject* old = cells[i];
    cells[i] = bigint_to_py(big[i]).release().ptr();
    Py_XDECREF(old);
  }
  return out;
}

// --- the other separable transforms ----------------------------------------------------

py::array voronoi_map_py(const py::object& obj, const std::string& metric, const py::object& torus,
                         unsigned threads) {
  // Read in place, C or F order. An F-ordered input is the C-ordered image of the reversed
  // axes: the map is computed there, returned F-ordered, and each site index (a C-order
  // index of the reversed shape) is re-encoded as the C-order index of the input's shape.
  MaskView in = mask_view(obj, true, "voronoi_map");
  TransformOptions opt = transform_options(metric, torus, threads, in.shape.size());
  if (in.fortran) std::reverse(opt.torus.begin(), opt.torus.end());
  const Domain dom(in.shape);
  VoronoiMap v = [&] {
    py::gil_scoped_release release;
    VoronoiMap r = voronoi_map(dom, in.data, opt, in.item);
    if (in.fortran) {
      const std::vector<std::int64_t> ext = in.shape; // reversed shape, C order
      const std::size_t d = ext.size();
      for (auto& s : r.site) {
        // Coordinates in the reversed shape (last axis fastest), then C index of the input's
        // shape (its axis k is the reversed shape's axis d - 1 - k).
        std::int64_t rest = s, c = 0;
        std::vector<std::int64_t> coord(d);
        for (std::size_t k = d; k-- > 0;) {
          coord[k] = rest % ext[k];
          rest /= ext[k];
        }
        for (std::size_t k = d; k-- > 0;) c = c * ext[k] + coord[k];
        s = c;
      }
    }
    return r;
  }();
  return owning_array(std::move(v.site), shape_of(in), in.fortran);
}

py::array reverse_distance_transform_py(const py::object& obj, const std::string& metric,
                                        const py::object& torus, unsigned threads) {
  py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> a =
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) throw py::type_error("reverse_distance_transform: expected an integer array");
  if (a.ndim() == 0 || a.size() == 0) {
    throw InvalidArgument("reverse_distance_transform: an empty or 0-dimensional array");
  }
  // ensure() returns the array itself when it is int64 and C-contiguous: read in place.
  std::vector<std::int64_t> shape(a.shape(), a.shape() + a.ndim());
  const Domain dom(shape);
  TransformOptions opt = transform_options(metric, torus, threads, shape.size());
  Image<std::uint8_t> r = [&] {
    py::gil_scoped_release release;
    return reverse_distance_transform(dom, a.data(), opt);
  }();
  return owning_array(std::move(r.values()), shape);
}

py::tuple reduced_medial_axis_py(const py::object& obj, const std::string& metric,
                                 const py::object& torus, unsigned threads) {
  MaskView in = mask_view(obj, true, "reduced_medial_axis"); // read in place, C or F order
  TransformOptions opt = transform_options(metric, torus, threads, in.shape.size());
  if (in.fortran) std::reverse(opt.torus.begin(), opt.torus.end());
  const Domain dom(in.shape);
  std::vector<MedialBall> balls = [&] {
    py::gil_scoped_release release;
    return reduced_medial_axis(dom, in.data, opt, in.item);
  }();
  const auto n = static_cast<std::int64_t>(balls.size());
  const std::int64_t d = static_cast<std::int64_t>(in.shape.size());
  std::vector<std::int64_t> centres(static_cast<std::size_t>(n * d)), values(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::int64_t k = 0; k < d; ++k) {
      // An F-ordered input was processed with its axes reversed: reverse the coordinates.
      const std::size_t src =
          in.fortran ? static_cast<std::size_t>(d - 1 - k) : static_cast<std::size_t>(k);
      centres[i * static_cast<std::size_t>(d) + static_cast<std::size_t>(k)] = balls[i].centre[src];
    }
    values[i] = balls[i].value;
  }
  return py::make_tuple(owning_array(std::move(centres), {n, d}),
                        owning_array(std::move(values), {n}));
}

py::tuple power_map_py(const py::object& obj, const std::string& metric, const py::object& torus,
                       unsigned threads) {
  py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> a =
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) throw py::type_error("power_map: expected an integer array of weights");
  if (a.ndim() == 0 || a.size() == 0) {
    throw InvalidArgument("power_map: an empty or 0-dimensional array");
  }
  // ensure() returns the array itself when it is int64 and C-contiguous: read in place.
  std::vector<std::int64_t> shape(a.shape(), a.shape() + a.ndim());
  const Domain dom(shape);
  TransformOptions opt = transform_options(metric, torus, threads, shape.size());
  PowerMap m = [&] {
    py::gil_scoped_release release;
    return power_map(dom, a.data(), opt);
  }();
  return py::make_tuple(owning_array(std::move(m.site), shape),
                        owning_array(std::move(m.negative), shape));
}

// --- topology -------------------------------------------------------------------------------

AdjacencyPair pair_of(const std::optional<std::string>& text, int dim) {
  return text ? parse_adjacency_pair(*text, dim) : default_adjacency_pair(dim);
}

py::tuple connected_components_py(const py::object& obj, int k, const std::string& phase,
                                  const std::string& order, unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "connected_components");
  ComponentOptions opt;
  if (phase == "object") {
    opt.phase = Phase::object;
  } else if (phase == "background") {
    opt.phase = Phase::background;
  } else {
    throw InvalidArgument("connected_components: phase '" + phase +
                          "' is not 'object' or 'background'");
  }
  if (order == "size") {
    opt.order = ComponentOrder::by_size;
  } else if (order == "scan") {
    opt.order = ComponentOrder::by_scan;
  } else {
    throw InvalidArgument("connected_components: order '" + order + "' is not 'size' or 'scan'");
  }
  opt.threads = threads;
  if (k == 0) k = img.dim() == 2 ? 8 : (img.dim() == 3 ? 26 : 2 * img.dim());
  Components c = [&] {
    py::gil_scoped_release release;
    return connected_components(img, k, opt);
  }();
  std::vector<std::int64_t> shape = img.domain().extents();
  py::array labels = owning_array(std::move(c.labels.values()), shape);
  py::array sizes = owning_array(std::move(c.sizes), {static_cast<std::int64_t>(c.sizes.size())});
  py::array_t<bool> border(static_cast<py::ssize_t>(c.touches_border.size()));
  for (std::size_t i = 0; i < c.touches_border.size(); ++i) {
    border.mutable_data()[i] = c.touches_border[i];
  }
  return py::make_tuple(labels, sizes, border);
}

py::dict betti_numbers_py(const py::object& obj, const std::optional<std::string>& adjacency,
                          unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "betti_numbers");
  AdjacencyPair pair = pair_of(adjacency, img.dim());
  BettiNumbers b = [&] {
    py::gil_scoped_release release;
    return betti_numbers(img, pair, threads);
  }();
  py::list betti;
  for (int k = 0; k < b.dim; ++k) betti.append(b.b[static_cast<std::size_t>(k)]);
  py::dict d;
  d["betti"] = py::tuple(betti);
  d["euler"] = b.euler;
  d["adjacency"] = pair.name();
  return d;
}

// The simple points of the object (zdg topology simple): uint8, 1 on the simple points.
py::array simple_points_py(const py::object& obj, const std::optional<std::string>& adjacency) {
  Image<std::uint8_t> img = image_of(obj, "simple_points");
  const AdjacencyPair pair = pair_of(adjacency, img.dim());
  Image<std::uint8_t> simple = [&] {
    py::gil_scoped_release release;
    return simple_point_mask(img, pair);
  }();
  std::vector<std::int64_t> shape = img.domain().extents();
  return owning_array(std::move(simple.values()), shape);
}

py::array thinning_py(const py::object& obj, const std::string& method, const std::string& skeleton,
                      const std::optional<std::string>& adjacency, unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "thinning");
  ThinningOptions opt;
  opt.pair = pair_of(adjacency, img.dim());
  opt.skeleton = parse_skeleton_kind(skeleton);
  opt.threads = threads;
  const bool critical = method == "critical-kernel";
  if (!critical && method != "sequential") {
    throw InvalidArgument("thinning: method '" + method + "' is not sequential or critical-kernel");
  }
  if (critical && !(opt.pair.object == 26 || opt.pair.object == 8)) {
    throw InvalidArgument("thinning: method critical-kernel needs adjacency " +
                          std::string(img.dim() == 3 ? "26,6" : "8,4") + " (got " +
                          opt.pair.name() + ")");
  }
  ThinningResult r = [&] {
    py::gil_scoped_release release;
    return critical ? critical_kernel_thinning(img, opt) : homotopic_thinning(img, opt);
  }();
  std::vector<std::int64_t> shape = img.domain().extents();
  return owning_array(std::move(r.skeleton.values()), shape);
}

// --- surfaces -------------------------------------------------------------------------------

/// Centre of every surfel (x, y, z): the middle of the face between its two voxels.
py::array surfel_centres(const ImageSurfels& s) {
  std::vector<double> c(static_cast<std::size_t>(3 * s.size()));
  for (std::int64_t i = 0; i < s.size(); ++i) {
    std::uint64_t code = s.codes[static_cast<std::size_t>(i)];
    Voxel v = s.grid.voxel(code_voxel(code));
    double p[3] = {double(v.x), double(v.y), double(v.z)};
    p[code_axis(code)] += code_positive(code) ? 0.5 : -0.5;
    for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(3 * i + k)] = p[k];
  }
  return owning_array(std::move(c), {s.size(), 3});
}

py::dict surfels_py(const py::object& obj, unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "surfels");
  ImageSurfels s = [&] {
    py::gil_scoped_release release;
    return image_surfels(img, threads);
  }();
  py::dict d;
  d["centres"] = surfel_centres(s);
  std::int64_t n = s.size();
  d["codes"] = owning_array(std::move(s.codes), {n});
  return d;
}

// The integral-invariant estimates, one row per surfel, added to d: 'mean', and with the
// principal curvatures 'k1', 'k2', 'gaussian', 'normal', 'd1', 'd2'.
void put_ii_estimates(py::dict& d, std::vector<double> mean,
                      const std::vector<IIPrincipalCurvatures>& pc) {
  if (!mean.empty() || pc.empty()) {
    const auto n = static_cast<std::int64_t>(mean.size());
    d["mean"] = owning_array(std::move(mean), {n});
    return;
  }
  const auto n = static_cast<std::int64_t>(pc.size());
  std::vector<double> k1(pc.size()), k2(pc.size()), m(pc.size()), gauss(pc.size()),
      normal(3 * pc.size()), d1(3 * pc.size()), d2(3 * pc.size());
  for (std::size_t i = 0; i < pc.size(); ++i) {
    k1[i] = pc[i].k1;
    k2[i] = pc[i].k2;
    m[i] = pc[i].mean();
    gauss[i] = pc[i].gaussian();
    const Point3<double>* vs[3] = {&pc[i].normal, &pc[i].d1, &pc[i].d2};
    std::vector<double>* outs[3] = {&normal, &d1, &d2};
    for (int j = 0; j < 3; ++j) {
      (*outs[j])[3 * i] = vs[j]->x;
      (*outs[j])[3 * i + 1] = vs[j]->y;
      (*outs[j])[3 * i + 2] = vs[j]->z;
    }
  }
  d["k1"] = owning_array(std::move(k1), {n});
  d["k2"] = owning_array(std::move(k2), {n});
  d["mean"] = owning_array(std::move(m), {n});
  d["gaussian"] = owning_array(std::move(gauss), {n});
  d["normal"] = owning_array(std::move(normal), {n, 3});
  d["d1"] = owning_array(std::move(d1), {n, 3});
  d["d2"] = owning_array(std::move(d2), {n, 3});
}

// The integral-invariant estimates at the surfels s of img, added to d (put_ii_estimates).
void add_ii_estimates(py::dict& d, const Image<std::uint8_t>& img, const ImageSurfels& s, double h,
                      double radius, bool principal, unsigned threads) {
  std::vector<double> mean;
  std::vector<IIPrincipalCurvatures> pc;
  {
    py::gil_scoped_release release;
    if (principal)
      pc = volume_ii_principal_curvatures(img, s, h, radius, threads);
    else
      mean = volume_ii_mean_curvature(img, s, h, radius, threads);
  }
  put_ii_estimates(d, std::move(mean), pc);
}

py::dict ii_curvature_py(const py::object& obj, double h, double radius, bool principal,
                         unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "ii_curvature");
  ImageSurfels s = [&] {
    py::gil_scoped_release release;
    return image_surfels(img, threads);
  }();
  py::dict d;
  d["centres"] = surfel_centres(s);
  const std::int64_t n = s.size();
  add_ii_estimates(d, img, s, h, radius, principal, threads);
  d["codes"] = owning_array(std::move(s.codes), {n});
  return d;
}

// A spacing argument: `dim` positive finite numbers, in array order ((z, y, x) or (y, x)).
std::vector<double> spacing_of(const py::object& spacing, int dim, const std::string& what) {
  std::vector<double> sp;
  for (py::handle v : py::iter(spacing)) sp.push_back(v.cast<double>());
  const bool ok = sp.size() == std::size_t(dim) && std::all_of(sp.begin(), sp.end(), [](double x) {
                    return x > 0 && std::isfinite(x);
                  });
  if (!ok)
    throw InvalidArgument(what + ": spacing must be " + (dim == 3 ? "three" : "two") +
                          " positive numbers (" + (dim == 3 ? "z, y, x" : "y, x") + ")");
  return sp;
}

// zdg surface's operation (operations/surface_operations.hpp) on the whole object, with its
// mesh; the estimates at step h and radius R (physical units) when asked.
// The mesh's vertices as x y z rows (the (n, 3) arrays of surface() and reconstruct()).
std::vector<double> flat_vertices(const PolygonMesh& m) {
  std::vector<double> xyz(3 * m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    xyz[3 * i] = m.vertices[i].x;
    xyz[3 * i + 1] = m.vertices[i].y;
    xyz[3 * i + 2] = m.vertices[i].z;
  }
  return xyz;
}

py::dict surface_py(const py::object& obj, const std::string& mesh,
                    const std::optional<std::string>& adjacency, const py::object& spacing,
                    const py::object& estimate, double h, const py::object& radius,
                    unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "surface");
  if (img.dim() != 3) throw InvalidArgument("surface: a 3D volume is needed");
  SurfaceOptions o;
  o.adjacency = pair_of(adjacency, 3);
  o.threads = threads;
  ObjectImage im;
  im.name = "surface";
  im.spacing = {1, 1, 1};
  const Domain& dom = img.domain();
  im.origin = {double(dom.lower(0)), double(dom.lower(1)), double(dom.lower(2))};
  if (!spacing.is_none()) im.spacing = spacing_of(spacing, 3, "surface");
  if (mesh != "primal" && mesh != "marching-cubes") {
    throw InvalidArgument("surface: mesh '" + mesh + "' is not 'primal' or 'marching-cubes'");
  }
  o.mesh = mesh == "primal" ? SurfaceMesh::primal : SurfaceMesh::marching_cubes;
  if (!estimate.is_none()) {
    if (mesh != "primal") {
      throw InvalidArgument("surface: estimates are per surfel, that is per face of the primal "
                            "mesh: use mesh='primal'");
    }
    const std::string what = py::str(estimate);
    if (what != "mean" && what != "principal") {
      throw InvalidArgument("surface: estimate '" + what + "' is not 'mean' or 'principal'");
    }
    if (radius.is_none()) throw InvalidArgument("surface: an estimate needs radius=R");
    const double R = radius.cast<double>();
    // 'principal': one pass of principal curvatures, whose k1, k2 and Gaussian curvature
    // become the mesh's fields.
    o.estimates = what == "mean" ? std::vector<std::string>{"ii-mean"}
                                 : std::vector<std::string>{"ii-k1", "ii-k2", "ii-gaussian"};
    o.radius = {R, false, py::str(radius).cast<std::string>()};
    o.step = h;
  }
  im.mask = std::move(img);
  SurfaceResult r = [&] {
    py::gil_scoped_release release;
    return surface_operation(std::move(im), o);
  }();
  PolygonMesh& m = *r.mesh;
  const std::int64_t nv = m.vertex_count(), nf = m.face_count();
  std::vector<double> xyz = flat_vertices(m);
  py::dict d;
  d["vertices"] = owning_array(std::move(xyz), {nv, 3});
  d["faces"] = owning_array(std::move(m.indices), {nf, static_cast<std::int64_t>(m.face_size)});
  d["adjacency"] = r.adjacency.name();
  d["betti"] = py::make_tuple(r.betti.b[0], r.betti.b[1], r.betti.b[2]);
  d["object_components"] = r.object_components;
  d["surfaces"] = r.surfaces;
  if (!o.estimates.empty()) put_ii_estimates(d, std::move(r.estimates.mean), r.estimates.principal);
  // The mesh's per-face fields and face normals, as zdg surface --html puts them on its page.
  py::dict fields;
  for (auto& field : m.face_scalars) {
    const auto n = static_cast<std::int64_t>(field.second.size());
    fields[py::str(field.first)] = owning_array(std::move(field.second), {n});
  }
  d["fields"] = fields;
  if (!m.face_normals.empty()) {
    std::vector<double> n3(3 * m.face_normals.size());
    for (std::size_t f = 0; f < m.face_normals.size(); ++f) {
      n3[3 * f] = m.face_normals[f].x;
      n3[3 * f + 1] = m.face_normals[f].y;
      n3[3 * f + 2] = m.face_normals[f].z;
    }
    d["face_normals"] = owning_array(std::move(n3), {nf, 3});
  }
  return d;
}

// zdg reconstruct's operation (operations/reconstruct_operations.hpp): points (n, 3) and
// optional normals (n, 3) in, the mesh and the topology of the reconstruction out.
std::vector<Point3<double>> triples_of(const py::object& obj, const char* what) {
  py::array a = py::array::ensure(obj);
  if (!a) throw InvalidArgument(std::string("reconstruct: ") + what + " is not an array");
  const char k = a.dtype().kind();
  if (!(k == 'i' || k == 'u' || k == 'f'))
    throw InvalidArgument(std::string("reconstruct: ") + what + " must hold numbers, not " +
                          std::string(py::str(a.dtype())));
  if (a.ndim() != 2 || a.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    throw InvalidArgument(std::string("reconstruct: ") + what + " has shape " + shape +
                          (a.ndim() == 1 ? ",)" : ")") + ", not (n, 3)");
  }
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<Point3<double>> out(static_cast<std::size_t>(d.shape(0)));
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = {d.data()[3 * i], d.data()[3 * i + 1], d.data()[3 * i + 2]};
  return out;
}

py::dict reconstruct_py(const py::object& points, const py::object& normals, double h,
                        const std::string& method, std::size_t k, std::size_t normals_k,
                        double beta, bool exact, std::size_t rbf_centers, double rbf_offset,
                        double imls_radius, int margin, unsigned threads) {
  PointCloud cloud;
  cloud.points = triples_of(points, "points");
  if (!normals.is_none()) cloud.normals = triples_of(normals, "normals");
  ReconstructOptions o;
  o.method.method = reconstruction_method_of(method);
  o.method.k = k;
  o.method.winding_beta = beta;
  o.method.winding_exact = exact;
  o.method.rbf_centers = rbf_centers;
  o.method.rbf_offset = rbf_offset;
  o.method.imls_radius = imls_radius;
  o.method.threads = threads;
  o.h = h;
  o.margin = margin;
  o.normals_k = normals_k;
  o.source = "reconstruct";
  ReconstructResult r = [&] {
    py::gil_scoped_release release;
    return reconstruct_operation(std::move(cloud), o);
  }();
  PolygonMesh& m = r.reconstruction.mesh;
  const std::int64_t nv = m.vertex_count(), nf = m.face_count();
  std::vector<double> xyz = flat_vertices(m);
  const auto& g = r.reconstruction.field.grid;
  py::dict d;
  d["vertices"] = owning_array(std::move(xyz), {nv, 3});
  d["faces"] = owning_array(std::move(m.indices), {nf, 3});
  d["field"] = owning_array(std::move(r.reconstruction.field.values), {g.nz, g.ny, g.nx});
  d["lower"] = py::make_tuple(g.lower[2], g.lower[1], g.lower[0]);
  d["h"] = h;
  const auto& b = r.reconstruction.betti;
  d["betti"] = py::make_tuple(b.b[0], b.b[1], b.b[2]);
  d["inside"] = r.reconstruction.inside_count;
  d["normals"] = r.normals_estimated ? "estimated" : "given";
  return d;
}

// zdg contour's operation (operations/surface_operations.hpp) on the whole 2D object: the
// contours as Freeman chains, the Betti numbers and the estimates asked for.
py::dict contour_py(const py::object& obj, const std::string& adjacency,
                    const std::vector<std::string>& estimates, const std::string& radius,
                    const py::object& spacing, unsigned threads) {
  Image<std::uint8_t> img = image_of(obj, "contour");
  if (img.dim() != 2) throw InvalidArgument("contour: a 2D image is needed");
  ContourOptions o;
  o.adjacency = parse_adjacency_pair(adjacency, 2);
  o.estimates = estimates;
  o.radius = parse_estimator_radius(radius);
  o.threads = threads;
  ObjectImage im;
  im.name = "contour";
  im.spacing = {1, 1};
  const Domain& dom = img.domain();
  im.origin = {double(dom.lower(0)), double(dom.lower(1))};
  if (!spacing.is_none()) im.spacing = spacing_of(spacing, 2, "contour");
  im.mask = std::move(img);
  ContourResult r = [&] {
    py::gil_scoped_release release;
    return contour_operation(std::move(im), o);
  }();
  py::list contours;
  const auto& req = r.request;
  const auto& e = r.estimates;
  for (std::size_t c = 0; c < r.contours.contours.size(); ++c) {
    const auto& k = r.contours.contours[c];
    py::dict d;
    d["start"] = py::make_tuple(k.start.x, k.start.y);
    std::vector<std::uint8_t> codes(k.codes.begin(), k.codes.end());
    const auto n = static_cast<std::int64_t>(codes.size());
    d["codes"] = owning_array(std::move(codes), {n});
    const auto area2 = k.twice_signed_area();
    d["pixels"] = area2 / 2;
    d["kind"] = area2 > 0 ? "outer" : "hole";
    if (req.ii_curvature)
      d["ii_curvature"] = owning_array(std::vector<double>(e.ii_curvature[c]), {n});
    for (const auto& [want, name, field] :
         {std::tuple{req.bc_tangent, "bc_tangent", &e.bc_tangent},
          std::tuple{req.lmst_tangent, "lmst_tangent", &e.lmst_tangent}}) {
      if (!want) continue;
      std::vector<double> xy;
      for (const auto& t : (*field)[c]) {
        xy.push_back(t.x);
        xy.push_back(t.y);
      }
      const auto m = static_cast<std::int64_t>((*field)[c].size());
      d[name] = owning_array(std::move(xy), {m, 2});
    }
    if (req.mlp_length) d["mlp_length"] = e.mlp_length[c];
    contours.append(d);
  }
  py::dict out;
  out["adjacency"] = r.adjacency.name();
  out["betti"] = py::make_tuple(r.betti.b[0], r.betti.b[1]);
  out["euler"] = r.betti.euler;
  out["linels"] = r.contours.linels();
  out["contours"] = contours;
  if (req.gauss_area) out["gauss_area"] = e.gauss_area;
  return out;
}

// --- viewer pages ---------------------------------------------------------------------------

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k)
    s += (k ? ", " : "") + std::to_string(a.shape(k)) + (a.ndim() == 1 ? "," : "");
  return s + ")";
}

/// `obj` as a C-contiguous array of T (a copy when its type or layout differ), after checking
/// that it holds numbers (integers only when `integral`; bools refused) and has `shape` (-1:
/// any extent); InvalidArgument naming `what` else.
template <class T>
py::array_t<T> numbers_of(const py::object& obj, const std::string& what, bool integral,
                          const std::vector<std::int64_t>& shape) {
  py::array a = py::array::ensure(obj);
  if (!a) throw InvalidArgument("view: " + what + " is not an array");
  const char k = a.dtype().kind();
  if (!(k == 'i' || k == 'u' || (!integral && k == 'f')))
    throw InvalidArgument("view: " + what + " must hold " + (integral ? "integers" : "numbers") +
                          ", not " + std::string(py::str(a.dtype())));
  bool ok = a.ndim() == py::ssize_t(shape.size());
  std::string want = "(";
  for (std::size_t d = 0; d < shape.size(); ++d) {
    ok = ok && (shape[d] < 0 || a.shape(py::ssize_t(d)) == shape[d]);
    want += (d ? ", " : "") + (shape[d] < 0 ? std::string("n") : std::to_string(shape[d]));
  }
  want += shape.size() == 1 ? ",)" : ")";
  if (!ok) throw InvalidArgument("view: " + what + " has shape " + shape_text(a) + ", not " + want);
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
}

/// Triples of numbers as points; InvalidArgument naming the first non-finite one.
std::vector<Point3<double>> finite_points(const py::array_t<double>& a, const char* what) {
  const double* p = a.data();
  std::vector<Point3<double>> out(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
      throw InvalidArgument(std::string("view: ") + what + " " + std::to_string(i) + " is (" +
                            std::to_string(out[i].x) + ", " + std::to_string(out[i].y) + ", " +
                            std::to_string(out[i].z) + "), not finite");
  }
  return out;
}

// The viewer page (kernel/render/mesh_html.hpp) of the mesh of the arrays: vertices (V, 3),
// faces (F, k) vertex indices, fields {name: (F,)} or None, face normals (F, 3) or None.
std::string mesh_html_py(const py::object& vertices, const py::object& faces,
                         const py::object& fields, const py::object& normals,
                         const std::string& title, const std::string& field,
                         std::int64_t max_faces) {
  if (max_faces < 1)
    throw InvalidArgument("view: max_faces is " + std::to_string(max_faces) + ", not positive");
  const auto fa = numbers_of<std::int64_t>(faces, "faces", true, {-1, -1});
  const std::int64_t nf = fa.shape(0);
  if (nf > max_faces)
    throw InvalidArgument("view: the page would hold " + std::to_string(nf) +
                          " faces, more than max_faces=" + std::to_string(max_faces) +
                          "; a browser would not open it smoothly");
  const auto va = numbers_of<double>(vertices, "vertices", false, {-1, 3});
  PolygonMesh mesh;
  mesh.face_size = static_cast<int>(fa.shape(1));
  mesh.indices.assign(fa.data(), fa.data() + fa.size());
  mesh.vertices = finite_points(va, "vertex");
  if (!fields.is_none()) {
    if (!py::isinstance<py::dict>(fields))
      throw InvalidArgument("view: fields must be a dict {name: per-face values}");
    for (const auto& [key, values] : py::reinterpret_borrow<py::dict>(fields)) {
      if (!py::isinstance<py::str>(key))
        throw InvalidArgument("view: a field name is " + std::string(py::repr(key)) +
                              ", not a str");
      const std::string name = py::str(key);
      const auto v = numbers_of<double>(py::reinterpret_borrow<py::object>(values),
                                        "field '" + name + "'", false, {nf});
      mesh.face_scalars.emplace_back(name, std::vector<double>(v.data(), v.data() + v.size()));
    }
  }
  if (!normals.is_none())
    mesh.face_normals =
        finite_points(numbers_of<double>(normals, "face normals", false, {nf, 3}), "face normal");
  MeshHtmlOptions o;
  o.title = title;
  o.field = field;
  o.max_faces = max_faces;
  py::gil_scoped_release release;
  return mesh_html(mesh, o);
}

void write_text_py(const py::object& path_arg, const std::string& text, bool force) {
  const std::string path = path_argument(path_arg, "write");
  py::gil_scoped_release release;
  write_file_atomically(path, text, force ? Existing::replace : Existing::refuse);
}

// --- volumes --------------------------------------------------------------------------------

struct DTypeName {
  DType t;
  const char* numpy;
};
constexpr DTypeName kDTypes[] = {
    {DType::Bool, "bool"},  {DType::U8, "uint8"},    {DType::U16, "uint16"}, {DType::U32, "uint32"},
    {DType::U64, "uint64"}, {DType::I8, "int8"},     {DType::I16, "int16"},  {DType::I32, "int32"},
    {DType::I64, "int64"},  {DType::F32, "float32"}, {DType::F64, "float64"}};

py::object read_volume_py(const py::object& path_arg, bool metadata) {
  const std::string path = path_argument(path_arg, "read_volume");
  ScalarVolume v = [&] {
    py::gil_scoped_release release;
    return read_volume(path);
  }();
  const char* name = nullptr;
  for (const auto& e : kDTypes) {
    if (e.t == v.array.dtype) name = e.numpy;
  }
  if (name == nullptr) throw InvalidArgument("read_volume: " + path + ": unsupported value type");
  // The array views the bytes read (owned by a capsule): no copy.
  auto* owned = new std::vector<unsigned char>(std::move(v.array.bytes));
  py::capsule free_when_done(owned,
                             [](void* p) { delete static_cast<std::vector<unsigned char>*>(p); });
  py::dtype dt(name);
  std::vector<py::ssize_t> shape(v.array.shape.begin(), v.array.shape.end());
  py::array a(dt, shape, {}, owned->data(), free_when_done);
  if (!metadata) return a;
  py::dict m;
  m["lower"] = v.lower;
  m["spacing"] = v.spacing;
  m["origin"] = v.origin;
  m["slope"] = v.slope;
  m["inter"] = v.inter;
  m["format"] = volume_format_name(volume_format_of(path));
  return py::make_tuple(a, m);
}

void write_volume_py(const py::object& path_arg, const py::object& obj, bool force) {
  const std::string path = path_argument(path_arg, "write_volume");
  py::array a = py::array::ensure(obj);
  if (!a) throw py::type_error("write_volume: expected a numpy array");
  py::module_ np = py::module_::import("numpy");
  std::string name = py::str(a.dtype().attr("name"));
  std::optional<DType> t;
  for (const auto& e : kDTypes) {
    if (name == e.numpy) t = e.t;
  }
  if (!t) {
    throw InvalidArgument("write_volume: dtype " + name +
                          " is not one of bool, (u)int8..64, float32, float64");
  }
  check_output_path(path, force ? Existing::replace : Existing::refuse);
  py::array c =
      np.attr("ascontiguousarray")(a, py::arg("dtype") = a.dtype().attr("newbyteorder")("="));
  NpyArray arr;
  arr.dtype = *t;
  for (py::ssize_t k = 0; k < c.ndim(); ++k) arr.shape.push_back(c.shape(k));
  const auto* bytes = static_cast<const unsigned char*>(c.data());
  arr.bytes.assign(bytes, bytes + c.nbytes());
  ScalarVolume v = make_scalar_volume(std::move(arr));
  py::gil_scoped_release release;
  write_volume(path, v);
}

// The chamfer transform of a 2D or 3D mask (kernel/transforms/chamfer_transform.hpp): uint64
// values (the classes of moves are symmetric under permuting the axes, so an F-ordered input is
// transformed as the C-ordered image of its reversed axes).
py::array chamfer_transform_py(const py::object& obj, const py::object& weights) {
  MaskView in = mask_view(obj, true, "chamfer_transform");
  const int d = static_cast<int>(in.shape.size());
  if (d != 2 && d != 3) {
    throw InvalidArgument("chamfer_transform: a " + std::to_string(d) +
                          "-D array (the masks are 2D or 3D)");
  }
  const ChamferMask mask = weights.is_none()
                               ? ChamferMask::borgefors(d)
                               : ChamferMask(d, weights.cast<std::vector<std::int64_t>>());
  Domain dom(in.shape);
  Image<std::uint8_t> img{dom};
  for (std::int64_t i = 0; i < in.size(); ++i) img.values()[std::size_t(i)] = in.object(i) ? 1 : 0;
  Image<std::uint64_t> r = [&] {
    py::gil_scoped_release release;
    return chamfer_transform<std::uint64_t>(img, mask);
  }();
  py::module_ np = py::module_::import("numpy");
  py::array_t<std::uint64_t> out = np.attr("empty")(shape_of(in), py::arg("dtype") = "uint64",
                                                    py::arg("order") = in.fortran ? "F" : "C");
  std::copy(r.values().begin(), r.values().end(), out.mutable_data());
  return out;
}

// The local thickness (kernel/transforms/local_thickness.hpp): float32 diameters, 0 off the
// object. The definition does not depend on the order of the axes (balls are Euclidean), so an
// F-ordered input is transformed as the C-ordered image of its reversed axes.
py::array local_thickness_py(const py::object& obj, unsigned threads) {
  MaskView in = mask_view(obj, true, "local_thickness");
  Domain dom(in.shape);
  Image<std::uint8_t> img{dom};
  for (std::int64_t i = 0; i < in.size(); ++i) img.values()[std::size_t(i)] = in.object(i) ? 1 : 0;
  TransformOptions opt;
  opt.threads = threads;
  Image<float> r = [&] {
    py::gil_scoped_release release;
    return local_thickness(img, opt);
  }();
  py::module_ np = py::module_::import("numpy");
  py::array_t<float> out = np.attr("empty")(shape_of(in), py::arg("dtype") = "float32",
                                            py::arg("order") = in.fortran ? "F" : "C");
  std::copy(r.values().begin(), r.values().end(), out.mutable_data());
  return out;
}

// Sparse voxel DAGs (kernel/images/voxel_dag.hpp) of a 3D array: voxel (x, y, z) is
// volume[z, y, x], nonzero = set.
VoxelDag dag_of(const py::object& volume, const std::string& kind, const char* what) {
  const VoxelDagKind k = parse_voxel_dag_kind(kind);
  Image<std::uint8_t> img = image_of(volume, what);
  if (img.domain().dim() != 3)
    throw InvalidArgument(std::string(what) + ": a 3D array is needed (got dimension " +
                          std::to_string(img.domain().dim()) + ")");
  py::gil_scoped_release release;
  return build_voxel_dag(img, k);
}

py::dict voxel_dag_py(const py::object& volume, const std::string& kind) {
  const VoxelDagStats s = dag_of(volume, kind, "voxel_dag").stats();
  py::dict d;
  d["kind"] = voxel_dag_kind_name(s.kind);
  d["depth"] = s.depth;
  d["voxels"] = s.voxels;
  d["nodes"] = s.inner_nodes;
  d["leaves"] = s.leaves;
  d["pointers"] = s.pointers;
  d["bytes"] = s.bytes;
  d["bits_per_voxel"] = s.bits_per_voxel();
  d["nodes_per_level"] = s.nodes_per_level;
  d["svo_nodes"] = s.svo_inner_nodes;
  d["svo_leaves"] = s.svo_leaves;
  d["svo_bytes"] = s.svo_bytes;
  return d;
}

py::list dag_ray_hits_py(const py::object& volume, const std::array<std::int64_t, 3>& origin,
                         const std::array<std::int64_t, 3>& vector, std::int64_t denominator,
                         const std::string& kind, const std::optional<std::int64_t>& max_hits) {
  if (max_hits && *max_hits < 0) throw InvalidArgument("dag_ray_hits: max_hits is negative");
  const VoxelDag g = dag_of(volume, kind, "dag_ray_hits");
  const auto hits =
      g.ray_hits({origin, vector, denominator}, max_hits ? static_cast<std::size_t>(*max_hits)
                                                         : std::numeric_limits<std::size_t>::max());
  py::list out;
  for (const auto& h : hits)
    out.append(py::make_tuple(py::make_tuple(h.voxel[0], h.voxel[1], h.voxel[2]), h.axis));
  return out;
}

} // namespace

void bind_arrays(py::module_& m) {
  m.def("distance_transform", &distance_transform_py, py::arg("image"), py::kw_only(),
        py::arg("metric") = "l2", py::arg("torus") = py::none(), py::arg("threads") = 0,
        "Exact distance transform of a binary image of any dimension (nonzero = object): at "
        "every point d_p^p to the nearest zero point (l2: the squared Euclidean distance; "
        "linf: d itself); zeros get 0. Separable lower envelopes (Hirata 1996, Meijster et "
        "al. 2000, Maurer et al. 2003), O(N d) for l1, l2, linf, O(N d log n) for other lp. "
        "metric: 'l1', 'l2', 'linf', 'lP' (1 <= P <= 1000); torus: per-axis periodic flags "
        "(or one bool). Zero-copy: a bool/int8/uint8 C- or F-contiguous input is read in "
        "place, the result is written straight into the returned array (int32, else int64: "
        "the narrowest type the proven bound on every intermediate allows, else an object "
        "array of exact Python ints). The GIL is "
        "released during the work.");
  m.def("chamfer_transform", &chamfer_transform_py, py::arg("image"), py::kw_only(),
        py::arg("mask") = py::none(),
        "Exact chamfer distance transform of a 2D or 3D binary image (nonzero = object): at "
        "every point the least total weight of a path of mask moves to a zero point "
        "(Borgefors 1986). mask: the weights of the classes of moves, 2D [axis, diagonal, "
        "knight] ([3, 4], [5, 7, 11]), 3D [face, edge, vertex] ([3, 4, 5]); default [3, 4] / "
        "[3, 4, 5]. Returns a uint64 array.");
  m.def("local_thickness", &local_thickness_py, py::arg("image"), py::kw_only(),
        py::arg("threads") = 0,
        "Local thickness of a binary image of dimension 1 to 6 (nonzero = object; Hildebrand, "
        "Ruegsegger 1997): at each object point the diameter 2 sqrt(R2) of the largest "
        "inscribed open Euclidean ball |y - c|^2 < DT(c) containing it (R2 exact, from the "
        "squared distance transform), 0 off the object. Returns a float32 array.");
  m.def("voronoi_map", &voronoi_map_py, py::arg("image"), py::kw_only(), py::arg("metric") = "l2",
        py::arg("torus") = py::none(), py::arg("threads") = 0,
        "Voronoi map of the zero points of a binary image: at every point the C-order linear "
        "index of a nearest zero point in l_p (ties to the smaller position on each line; the "
        "separable engine of distance_transform, O(N d)). Returns an int64 array.");
  m.def("reverse_distance_transform", &reverse_distance_transform_py, py::arg("values"),
        py::kw_only(), py::arg("metric") = "l2", py::arg("torus") = py::none(),
        py::arg("threads") = 0,
        "Reverse distance transform: the union of the open balls {x : d_p(x, c)^p < v(c)} over "
        "the points c of value v(c) > 0 (the inverse of distance_transform on its medial "
        "balls; Coeurjolly and Montanvert 2007), separable, O(N d). Returns uint8 (1 inside).");
  m.def("reduced_medial_axis", &reduced_medial_axis_py, py::arg("image"), py::kw_only(),
        py::arg("metric") = "l2", py::arg("torus") = py::none(), py::arg("threads") = 0,
        "Reduced discrete medial axis of the object: the maximal balls whose union is the "
        "object (power diagram of the distance transform, Coeurjolly and Montanvert 2007), "
        "O(N d). Returns (centres (n, d) int64, values int64: the squared radii for l2).");
  m.def("connected_components", &connected_components_py, py::arg("image"), py::arg("k") = 0,
        py::kw_only(), py::arg("phase") = "object", py::arg("order") = "size",
        py::arg("threads") = 0,
        "k-connected components of the object (phase 'object': nonzero points) or of the "
        "background (zeros) of a binary image (k: 4/8 in 2D, 6/18/26 in 3D, 2d or 3^d-1 in d "
        "dimensions; 0: 8 in 2D, 26 in 3D). Union-find over scan lines, O(N alpha(N)). "
        "Returns (labels uint32 array, 0 off the phase and 1.. for the components, numbered by "
        "decreasing size or scan order; sizes int64; touches_border bool).");
  m.def("betti_numbers", &betti_numbers_py, py::arg("image"), py::arg("adjacency") = py::none(),
        py::kw_only(), py::arg("threads") = 0,
        "Betti numbers (b0, b1[, b2]) and Euler characteristic of the object of a 2D or 3D "
        "binary image for the adjacency pair 'object,background' (default 8,4 / 26,6): b0 "
        "and b2 from component counts, chi from the 2x2(x2) block configurations, b1 by "
        "Euler-Poincare. O(N). Returns {'betti', 'euler', 'adjacency'}.");
  m.def("simple_points", &simple_points_py, py::arg("image"), py::kw_only(),
        py::arg("adjacency") = py::none(),
        "The simple points of the object of a 2D or 3D binary image under the adjacency pair "
        "(default 8,4 / 26,6): the points whose removal keeps the topology (the definition on "
        "the 3^d neighbourhood). Returns a uint8 array, 1 on the simple points.");
  m.def("thinning", &thinning_py, py::arg("image"), py::kw_only(),
        py::arg("method") = "critical-kernel", py::arg("skeleton") = "ultimate",
        py::arg("adjacency") = py::none(), py::arg("threads") = 0,
        "Homotopic thinning of the object of a 2D or 3D binary image: 'critical-kernel' "
        "(parallel, Bertrand and Couprie) or 'sequential' (simple points deleted by increasing "
        "exact distance to the background); skeleton 'ultimate', 'curve', 'surface' or "
        "'medial-axis'. The result (uint8, 1 on kept points) has the topology of the input.");
  m.def("surfels", &surfels_py, py::arg("volume"), py::kw_only(), py::arg("threads") = 0,
        "Boundary surfels of the nonzero voxels of a 3D image (axes z, y, x; outside the array "
        "is outside): sorted 64-bit codes (8 * voxel index + 2 * axis + positive side) and "
        "their centres (x, y, z). O(N). Returns {'codes', 'centres'}.");
  m.def("ii_curvature", &ii_curvature_py, py::arg("volume"), py::kw_only(), py::arg("h"),
        py::arg("radius"), py::arg("principal") = false, py::arg("threads") = 0,
        "Integral-invariant curvature (Coeurjolly, Lachaud, Levallois, CVIU 2014) at every "
        "boundary surfel of a 3D binary volume at grid step h and kernel radius R (physical "
        "units, R/h <= 256 voxels): mean curvature, and with principal=True k1 <= k2, Gaussian "
        "curvature, unit normal and principal directions. About 2 pi (R/h)^2 look-ups per "
        "surfel. Returns {'codes', 'centres', 'mean', ...}.");
  m.def("power_map", &power_map_py, py::arg("weights"), py::kw_only(), py::arg("metric") = "l2",
        py::arg("torus") = py::none(), py::arg("threads") = 0,
        "Exact discrete power map of the weighted sites (points of weight > 0) of an integer "
        "array of any dimension, for l_p with p finite (Coeurjolly and Montanvert, PAMI 2007): "
        "at every point the C-order linear index of a site minimising d_p(x, c)^p - w(c), and "
        "whether that minimal power is negative (the point lies in the site's open ball). "
        "O(N d) for l1, l2. Returns (site, negative) arrays of the weights' shape.");
  m.def("surface", &surface_py, py::arg("volume"), py::kw_only(), py::arg("mesh") = "primal",
        py::arg("adjacency") = py::none(), py::arg("spacing") = py::none(),
        py::arg("estimate") = py::none(), py::arg("h") = 1.0, py::arg("radius") = py::none(),
        py::arg("threads") = 0,
        "The boundary of the nonzero voxels of a 3D volume (axes z, y, x) as a mesh: 'primal' "
        "(one quad per surfel, vertices at the pointels) or 'marching-cubes' (triangles), "
        "ambiguities resolved by the adjacency pair ('6,26' default, '26,6', '6,18', '18,6'); "
        "spacing (sz, sy, sx) scales the vertices. Returns {'vertices' (n, 3) float64 as x, y, "
        "z (x along the last axis), 'faces' (m, 4 or 3) int64, counter-clockwise from outside, "
        "'adjacency', 'fields' {name: (m,) float64}, the per-face fields of zdg surface's mesh "
        "and viewer page, 'face_normals' (m, 3) (primal mesh)}, the mesh zdg surface writes as "
        "PLY (zdg.view shows it). estimate='mean' or 'principal' (primal "
        "mesh only: face f is surfel f) adds the integral-invariant estimates per face at grid "
        "step h and radius R, as ii_curvature returns them.");
  m.def("reconstruct", &reconstruct_py, py::arg("points"), py::arg("normals") = py::none(),
        py::kw_only(), py::arg("h"), py::arg("method") = "hoppe", py::arg("k") = 10,
        py::arg("normals_k") = 10, py::arg("beta") = 2.0, py::arg("exact") = false,
        py::arg("rbf_centers") = 1000, py::arg("rbf_offset") = 0.0, py::arg("imls_radius") = 0.0,
        py::arg("margin") = 3, py::arg("threads") = 0,
        "A surface from points (n, 3) with optional outward normals (n, 3; estimated by PCA "
        "and oriented over the MST when None), as zdg reconstruct computes it: the field of "
        "method ('hoppe', 'winding', 'poisson', 'rbf', 'imls') on the lattice h Z^3 (negative "
        "inside), the digitization of its negative set and its marching-cubes mesh: "
        "{'vertices' (m, 3), 'faces' (f, 3), 'field' (nz, ny, nx), 'lower' (z, y, x index of "
        "field[0, 0, 0]: the sample h * lower), 'h', 'betti' (b0, b1, b2), 'inside', "
        "'normals' ('given' or 'estimated')}.");
  m.def("contour", &contour_py, py::arg("image"), py::kw_only(), py::arg("adjacency") = "4,8",
        py::arg("estimates") = std::vector<std::string>{}, py::arg("radius") = "5v",
        py::arg("spacing") = py::none(), py::arg("threads") = 0,
        "The contours of the nonzero pixels of a 2D image (axes y, x) under the adjacency pair "
        "('4,8' default or '8,4'), as zdg contour computes them: {'adjacency', 'betti' (b0, b1), "
        "'euler', 'linels', 'contours': [{'start' (x, y), 'codes' (Freeman codes, uint8), "
        "'pixels' (signed area: negative for a hole), 'kind' ('outer' or 'hole'), and per "
        "estimate 'ii_curvature' (per linel), 'bc_tangent', 'lmst_tangent' ((n, 2) per pointel), "
        "'mlp_length'}], 'gauss_area'}. estimates: names among ii-curvature, bc-tangent, "
        "lmst-tangent, mlp-length, gauss-area; radius 'R' (physical units) or 'Rv' (pixels); "
        "spacing (sy, sx), equal for the estimates.");
  m.def("mesh_html", &mesh_html_py, py::arg("vertices"), py::arg("faces"),
        py::arg("fields") = py::none(), py::arg("normals") = py::none(), py::kw_only(),
        py::arg("title") = MeshHtmlOptions{}.title, py::arg("field") = "",
        py::arg("max_faces") = MeshHtmlOptions{}.max_faces,
        "The self-contained viewer page of zdg surface --html (WebGL, no network) of a mesh: "
        "vertices (V, 3) numbers, faces (F, k >= 3) vertex indices counter-clockwise from "
        "outside, fields {name: (F,) numbers} (non-finite values are shown as 'no value') or "
        "None, face normals (F, 3) or None; field: the one shown first ('': the first). "
        "Non-finite vertices or normals, indices out of range, wrong shapes or more than "
        "max_faces faces raise ValueError. Returns the page's text (zdg.view wraps it).");
  m.def("_write_text", &write_text_py, py::arg("path"), py::arg("text"), py::kw_only(),
        py::arg("force") = false,
        "Writes text (UTF-8) to path atomically (a staging file renamed in place); an "
        "existing file is refused unless force=True.");
  m.def("voxel_dag", &voxel_dag_py, py::arg("volume"), py::kw_only(), py::arg("kind") = "ssvdag",
        "Sizes of the sparse voxel octree ('svo'), DAG ('dag': equal subtrees once, Kampe et "
        "al. 2013) or symmetry-aware DAG ('ssvdag': equal up to a reflection, Villanueva et "
        "al. 2016) of a 3D array (voxel (x, y, z) is volume[z, y, x], nonzero = set): "
        "{'kind', 'depth', 'voxels', 'nodes', 'leaves', 'pointers', 'bytes', "
        "'bits_per_voxel', 'nodes_per_level' (root first), 'svo_nodes', 'svo_leaves', "
        "'svo_bytes'}; 32-bit headers and pointers, 64-bit leaves of 4^3 voxels.");
  m.def("dag_ray_hits", &dag_ray_hits_py, py::arg("volume"), py::arg("origin"), py::arg("vector"),
        py::arg("denominator") = 1, py::kw_only(), py::arg("kind") = "ssvdag",
        py::arg("max_hits") = py::none(),
        "The set voxels of a 3D array (voxel (x, y, z) is volume[z, y, x]) that the line "
        "(origin + t vector) / denominator (integers, voxel coordinates x, y, z) crosses "
        "over a positive length, in the line's order, exact: [((x, y, z), axis), ...], axis "
        "the face the line enters the voxel by; at most max_hits. Traverses the DAG of the "
        "array (built by the call: O(N) first).");
  m.def("read_volume", &read_volume_py, py::arg("path"), py::kw_only(), py::arg("metadata") = false,
        "Reads a volume (.vol v2/v3, .nii, .nii.gz, .npy, .pgm; path: str, bytes or "
        "os.PathLike) into a numpy array of its "
        "stored value type (no copy after the read); metadata=True also returns {'lower', "
        "'spacing', 'origin', 'slope', 'inter', 'format'}.");
  m.def("write_volume", &write_volume_py, py::arg("path"), py::arg("array"), py::kw_only(),
        py::arg("force") = false,
        "Writes a numpy array as a volume in the format of the file name (.vol, .nii, .nii.gz, "
        ".npy, .pgm; path: str, bytes or os.PathLike), atomically; an existing file is refused "
        "unless force=True.");
}

} // namespace zdg::python
