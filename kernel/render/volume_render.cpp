#include <zdg/arith/error.hpp>
#include <zdg/arith/point.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/render/volume_render.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <sstream>

namespace zdg {

// ---- transfer functions ----------------------------------------------------------------------

void TransferFunction::validate(const std::string& where) const {
  if (points.empty()) throw InvalidArgument(where + ": a transfer function needs a control point");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const std::string at = where + ": control point " + std::to_string(i + 1);
    if (!std::isfinite(p.value)) throw InvalidArgument(at + ": the value is not finite");
    if (i > 0 && !(p.value > points[i - 1].value))
      throw InvalidArgument(at + ": value " + short_number(p.value, 10) +
                            " does not increase (previous " +
                            short_number(points[i - 1].value, 10) + ")");
    for (double c : {p.r, p.g, p.b, p.alpha})
      if (!(c >= 0.0 && c <= 1.0))
        throw InvalidArgument(at + ": colour and opacity must lie in [0, 1] (got " +
                              short_number(c, 10) + ")");
  }
}

Rgba TransferFunction::operator()(double v) const {
  if (std::isnan(v) || points.empty()) return {};
  auto rgba = [](const TransferPoint& p) { return Rgba{p.r, p.g, p.b, p.alpha}; };
  if (v <= points.front().value) return rgba(points.front());
  if (v >= points.back().value) return rgba(points.back());
  const auto hi = std::upper_bound(points.begin(), points.end(), v,
                                   [](double x, const TransferPoint& p) { return x < p.value; });
  const auto& b = *hi;
  const auto& a = *(hi - 1);
  const double s = (v - a.value) / (b.value - a.value);
  return {a.r + s * (b.r - a.r), a.g + s * (b.g - a.g), a.b + s * (b.b - a.b),
          a.alpha + s * (b.alpha - a.alpha)};
}

TransferFunction parse_transfer_function(std::string_view text, const std::string& where) {
  TransferFunction tf;
  std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '{') {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
      std::string what = e.what();
      std::replace_if(
          what.begin(), what.end(), [](char c) { return static_cast<unsigned char>(c) < 32; }, '?');
      throw IoError(where + ": not valid JSON (" + what + ")");
    }
    if (!j.is_object() || !j.contains("points") || !j["points"].is_array())
      throw IoError(where + ": expected {\"points\": [[value, r, g, b, alpha], ...]}");
    std::size_t k = 0;
    for (const auto& p : j["points"]) {
      ++k;
      if (!p.is_array() || p.size() != 5)
        throw IoError(where + ": point " + std::to_string(k) +
                      ": expected [value, r, g, b, alpha]");
      double v[5];
      for (std::size_t i = 0; i < 5; ++i) {
        if (!p[i].is_number())
          throw IoError(where + ": point " + std::to_string(k) + ": entry " +
                        std::to_string(i + 1) + " is not a number");
        v[i] = p[i].get<double>();
      }
      tf.points.push_back({v[0], v[1], v[2], v[3], v[4]});
    }
  } else {
    std::size_t line_no = 0, pos = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      std::string line(text.substr(pos, end - pos));
      pos = end + 1;
      ++line_no;
      if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      for (char c : line)
        if (static_cast<unsigned char>(c) < 32 && c != '\t' && c != '\r')
          throw IoError(where + ":" + std::to_string(line_no) + ": a control character");
      std::istringstream in(line);
      in.imbue(std::locale::classic());
      TransferPoint p;
      std::string rest;
      if (!(in >> p.value >> p.r >> p.g >> p.b >> p.alpha) || (in >> rest))
        throw IoError(where + ":" + std::to_string(line_no) +
                      ": expected 'value r g b alpha' (five numbers)");
      tf.points.push_back(p);
    }
  }
  try {
    tf.validate(where);
  } catch (const InvalidArgument& e) {
    throw IoError(e.what());
  }
  return tf;
}

TransferFunction read_transfer_function(const std::string& path) {
  return parse_transfer_function(read_input_file(path, std::uint64_t{1} << 20), path);
}

std::vector<std::string> transfer_function_presets() {
  return {"grey", "ct-bone", "ct-soft-tissue"};
}

TransferFunction transfer_function_preset(const std::string& name, double lo, double hi) {
  TransferFunction tf;
  if (name == "grey") {
    if (!std::isfinite(lo) || !std::isfinite(hi))
      throw InvalidArgument("transfer function grey: the value range is not finite");
    if (!(hi > lo)) hi = lo + 1.0;
    tf.points = {{lo, 0, 0, 0, 0}, {hi, 1, 1, 1, 1}};
  } else if (name == "ct-bone") {
    // Hounsfield units: air and soft tissue transparent, bone from 200 HU ivory and opaque.
    tf.points = {{150, 0, 0, 0, 0},
                 {200, 0.80, 0.55, 0.40, 0.05},
                 {500, 0.95, 0.90, 0.80, 0.40},
                 {1500, 1.00, 1.00, 0.95, 0.90}};
  } else if (name == "ct-soft-tissue") {
    // Fat (-100 HU) faint yellow, muscle and organs (40 HU) red, bone white and opaque.
    tf.points = {{-600, 0, 0, 0, 0},
                 {-100, 0.90, 0.80, 0.40, 0.01},
                 {40, 0.80, 0.25, 0.20, 0.04},
                 {300, 1.00, 0.95, 0.90, 0.50},
                 {1500, 1.00, 1.00, 1.00, 0.90}};
  } else {
    std::string names;
    for (const auto& n : transfer_function_presets()) names += (names.empty() ? "" : ", ") + n;
    throw InvalidArgument("transfer function '" + name + "': no such preset (" + names + ")");
  }
  return tf;
}

// ---- camera ----------------------------------------------------------------------------------

namespace {

using V3 = Point3<double>;

struct Camera {
  V3 centre, right, up, toward;     // physical coordinates; toward: from the centre to the camera
  double u0 = 0, v0 = 0, pixel = 1; // the picture's centre (right, up) and pixel size
  std::array<double, 3> spacing{1, 1, 1};
  double depth = 0; // distance from the centre to the rays' origins
};

Camera make_camera(const std::array<std::int64_t, 3>& extent, const std::array<double, 3>& spacing,
                   const VolumeRenderOptions& o) {
  for (double s : spacing)
    if (!(s > 0) || !std::isfinite(s))
      throw InvalidArgument("render volume: the spacing must be positive and finite");
  Camera c;
  c.spacing = spacing;
  // Reduced modulo a turn first (exact): a huge angle in degrees would overflow in radians.
  const double a = std::fmod(o.azimuth, 360.0) * std::numbers::pi / 180,
               e = std::fmod(o.elevation, 360.0) * std::numbers::pi / 180;
  c.toward = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
  c.right = {-std::sin(a), std::cos(a), 0.0};
  c.up = cross(c.toward, c.right);
  // The physical box [-s/2, (n - 1/2) s] per axis, voxel i centred at i s.
  V3 lo{-spacing[0] / 2, -spacing[1] / 2, -spacing[2] / 2};
  V3 hi{(double(extent[0]) - 0.5) * spacing[0], (double(extent[1]) - 0.5) * spacing[1],
        (double(extent[2]) - 0.5) * spacing[2]};
  c.centre = 0.5 * (lo + hi);
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300, radius = 0;
  for (int k = 0; k < 8; ++k) {
    const V3 p{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const V3 q = p - c.centre;
    umin = std::min(umin, dot(q, c.right));
    umax = std::max(umax, dot(q, c.right));
    vmin = std::min(vmin, dot(q, c.up));
    vmax = std::max(vmax, dot(q, c.up));
    radius = std::max(radius, std::sqrt(dot(q, q)));
  }
  c.u0 = (umin + umax) / 2;
  c.v0 = (vmin + vmax) / 2;
  c.pixel = std::max((umax - umin) / (0.92 * o.width), (vmax - vmin) / (0.92 * o.height));
  if (!(c.pixel > 0)) c.pixel = 1;
  c.depth = 2 * radius + 1;
  return c;
}

constexpr double kRayDen = double(std::int64_t{1} << 20);
constexpr std::int64_t kMaxRayTerm = std::int64_t{1} << 42; // digital_ray.hpp's bounds
constexpr std::int64_t kMaxExtent = std::int64_t{1} << 20;

DigitalRay camera_ray(const Camera& c, const VolumeRenderOptions& o, int px, int py) {
  const double u = c.u0 + (px + 0.5 - o.width / 2.0) * c.pixel;
  const double v = c.v0 - (py + 0.5 - o.height / 2.0) * c.pixel;
  const V3 p = c.centre + u * c.right + v * c.up + c.depth * c.toward;
  // Voxel coordinates: x_vox = x / s; the direction scaled to a largest component of 1.
  const double pv[3] = {p.x / c.spacing[0], p.y / c.spacing[1], p.z / c.spacing[2]};
  double dv[3] = {-c.toward.x / c.spacing[0], -c.toward.y / c.spacing[1],
                  -c.toward.z / c.spacing[2]};
  const double m = std::max({std::abs(dv[0]), std::abs(dv[1]), std::abs(dv[2])});
  DigitalRay r;
  r.denominator = std::int64_t{1} << 20;
  for (int a = 0; a < 3; ++a) {
    const double on = std::nearbyint(pv[a] * kRayDen);
    if (!(std::abs(on) <= double(kMaxRayTerm)))
      throw InvalidArgument("render volume: the volume is too large for the camera's rays");
    r.origin[a] = static_cast<std::int64_t>(on);
    r.direction[a] = static_cast<std::int64_t>(std::nearbyint(dv[a] / m * kRayDen));
  }
  return r;
}

// The volume's values in place, as doubles (physical: slope and intercept applied), inlined
// on the samples' hot path rather than called through ScalarVolume::value (bench/README.md).
struct Values {
  const unsigned char* bytes = nullptr;
  DType type = DType::U8;
  std::size_t size = 1;
  double slope = 1, inter = 0;
  bool scaled = false;
  std::array<std::int64_t, 3> n{}; // x, y, z

  template <class T>
  static double load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return static_cast<double>(v);
  }
  double raw(std::int64_t i) const {
    const unsigned char* p = bytes + static_cast<std::size_t>(i) * size;
    switch (type) {
    case DType::Bool:
    case DType::U8:
      return *p;
    case DType::I8:
      return load<std::int8_t>(p);
    case DType::U16:
      return load<std::uint16_t>(p);
    case DType::I16:
      return load<std::int16_t>(p);
    case DType::U32:
      return load<std::uint32_t>(p);
    case DType::I32:
      return load<std::int32_t>(p);
    case DType::U64:
      return load<std::uint64_t>(p);
    case DType::I64:
      return load<std::int64_t>(p);
    case DType::F32:
      return load<float>(p);
    case DType::F64:
      return load<double>(p);
    }
    return 0;
  }
  double at(std::int64_t x, std::int64_t y, std::int64_t z) const {
    const double v = raw((z * n[1] + y) * n[0] + x);
    return scaled ? slope * v + inter : v;
  }
};

// Trilinear value and gradient (voxel coordinates) at p, the volume extended by its boundary.
double trilinear(const Values& vol, const double p[3], double grad[3]) {
  std::int64_t i0[3], i1[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double n1 = double(vol.n[a] - 1);
    const double q = std::clamp(p[a], 0.0, n1);
    std::int64_t k = static_cast<std::int64_t>(std::floor(q));
    if (k > vol.n[a] - 2) k = std::max<std::int64_t>(vol.n[a] - 2, 0);
    i0[a] = k;
    i1[a] = std::min(k + 1, vol.n[a] - 1);
    f[a] = vol.n[a] == 1 ? 0.0 : q - double(k);
  }
  double c[2][2][2];
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        c[z][y][x] = vol.at(x ? i1[0] : i0[0], y ? i1[1] : i0[1], z ? i1[2] : i0[2]);
  auto lerp = [](double a, double b, double t) { return a + t * (b - a); };
  const double c00 = lerp(c[0][0][0], c[0][0][1], f[0]), c01 = lerp(c[0][1][0], c[0][1][1], f[0]);
  const double c10 = lerp(c[1][0][0], c[1][0][1], f[0]), c11 = lerp(c[1][1][0], c[1][1][1], f[0]);
  const double c0 = lerp(c00, c01, f[1]), c1 = lerp(c10, c11, f[1]);
  // Partial derivatives of the interpolant (zero along an axis of extent 1 and outside the
  // box on a clamped axis, where the extension is constant).
  const double dx00 = c[0][0][1] - c[0][0][0], dx01 = c[0][1][1] - c[0][1][0];
  const double dx10 = c[1][0][1] - c[1][0][0], dx11 = c[1][1][1] - c[1][1][0];
  grad[0] = lerp(lerp(dx00, dx01, f[1]), lerp(dx10, dx11, f[1]), f[2]);
  grad[1] = lerp(c01 - c00, c11 - c10, f[2]);
  grad[2] = c1 - c0;
  for (int a = 0; a < 3; ++a)
    if (vol.n[a] == 1 || p[a] < 0 || p[a] > double(vol.n[a] - 1)) grad[a] = 0;
  return lerp(c0, c1, f[2]);
}

} // namespace

void VolumeRenderOptions::validate() const {
  check_picture_size(width, height, "render volume");
  if (!std::isfinite(azimuth) || !std::isfinite(elevation))
    throw InvalidArgument("render volume: the view angles must be finite");
  if (!(step >= 0.01 && step <= 8))
    throw InvalidArgument("render volume: the step must lie in [0.01, 8] voxels (got " +
                          short_number(step, 10) + ")");
  if (!(early_termination > 0 && early_termination <= 1))
    throw InvalidArgument("render volume: the early termination opacity must lie in (0, 1] (got " +
                          short_number(early_termination, 10) + ")");
}

DigitalRay volume_camera_ray(const std::array<std::int64_t, 3>& extent,
                             const std::array<double, 3>& spacing,
                             const VolumeRenderOptions& options, int px, int py) {
  options.validate();
  return camera_ray(make_camera(extent, spacing, options), options, px, py);
}

VolumeRendering render_volume(const ScalarVolume& volume, const TransferFunction& tf,
                              const VolumeRenderOptions& o) {
  volume.validate();
  tf.validate("transfer function");
  o.validate();
  const auto& sh = volume.array.shape;
  const bool flat = sh.size() == 2;
  Values vol;
  vol.bytes = volume.array.bytes.data();
  vol.type = volume.array.dtype;
  vol.size = dtype_size(vol.type);
  vol.slope = volume.slope;
  vol.inter = volume.inter;
  vol.scaled = volume.scaled();
  vol.n = flat ? std::array<std::int64_t, 3>{sh[1], sh[0], 1}
               : std::array<std::int64_t, 3>{sh[2], sh[1], sh[0]};
  for (auto e : vol.n)
    if (e > kMaxExtent)
      throw InvalidArgument("render volume: extents above 2^20 voxels are not supported");
  const std::array<double, 3> spacing =
      flat ? std::array<double, 3>{volume.spacing[1], volume.spacing[0], 1.0}
           : std::array<double, 3>{volume.spacing[2], volume.spacing[1], volume.spacing[0]};
  const Camera cam = make_camera(vol.n, spacing, o);

  VolumeRendering out;
  out.picture = RgbImage(o.width, o.height, Rgb{0, 0, 0});
  out.values.assign(static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height),
                    std::numeric_limits<double>::quiet_NaN());
  std::vector<std::int64_t> rays(static_cast<std::size_t>(o.height), 0),
      samples(static_cast<std::size_t>(o.height), 0);
  auto to8 = [](double c) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
  };
  // The headlight in voxel-gradient terms: n_phys = grad_vox / spacing.
  parallel_for(o.height, o.threads, [&](std::int64_t py) {
    for (int px = 0; px < o.width; ++px) {
      const DigitalRay r = camera_ray(cam, o, px, static_cast<int>(py));
      const std::size_t pix = static_cast<std::size_t>(py) * std::size_t(o.width) + std::size_t(px);
      if (o.mip) {
        double best = -std::numeric_limits<double>::infinity();
        std::int64_t seen = 0;
        for_each_ray_voxel(r, vol.n, [&](const std::array<std::int64_t, 3>& v) {
          best = std::max(best, vol.at(v[0], v[1], v[2]));
          ++seen;
        });
        if (seen == 0) continue;
        ++rays[std::size_t(py)];
        samples[std::size_t(py)] += seen;
        out.values[pix] = best;
        const Rgba c = tf(best);
        out.picture.set(px, static_cast<int>(py), Rgb{to8(c.r), to8(c.g), to8(c.b)});
        continue;
      }
      const RayChord ch = digital_ray_chord(r, vol.n);
      if (!ch.hit) continue;
      const double den = double(r.denominator);
      const double org[3] = {double(r.origin[0]) / den, double(r.origin[1]) / den,
                             double(r.origin[2]) / den};
      const double dir[3] = {double(r.direction[0]) / den, double(r.direction[1]) / den,
                             double(r.direction[2]) / den};
      const double t0 = double(ch.in.n) / double(ch.in.d), t1 = double(ch.out.n) / double(ch.out.d);
      const double speed = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
      const double length = (t1 - t0) * speed;
      const auto steps =
          std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(length / o.step - 1e-9)));
      const double dt = (t1 - t0) / double(steps), seg = length / double(steps);
      double cr = 0, cg = 0, cb = 0, alpha = 0;
      std::int64_t k = 0;
      for (; k < steps && alpha < o.early_termination; ++k) {
        const double t = t0 + (double(k) + 0.5) * dt;
        const double p[3] = {org[0] + t * dir[0], org[1] + t * dir[1], org[2] + t * dir[2]};
        double g[3];
        const double value = trilinear(vol, p, g);
        const Rgba c = tf(value);
        if (c.a <= 0) continue;
        const double as = c.a >= 1 ? 1.0 : 1.0 - std::pow(1.0 - c.a, seg);
        double shade = 1.0;
        if (o.shading) {
          const V3 n{g[0] / spacing[0], g[1] / spacing[1], g[2] / spacing[2]};
          const double norm = std::sqrt(dot(n, n));
          if (norm > 0) shade = 0.3 + 0.7 * std::abs(dot(n, cam.toward)) / norm;
        }
        const double w = (1 - alpha) * as;
        cr += w * c.r * shade;
        cg += w * c.g * shade;
        cb += w * c.b * shade;
        alpha += w;
      }
      ++rays[std::size_t(py)];
      samples[std::size_t(py)] += k;
      out.values[pix] = alpha;
      out.picture.set(px, static_cast<int>(py), Rgb{to8(cr), to8(cg), to8(cb)});
    }
  });
  for (std::size_t i = 0; i < rays.size(); ++i) {
    out.rays += rays[i];
    out.samples += samples[i];
  }
  return out;
}

} // namespace zdg
