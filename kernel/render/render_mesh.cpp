#include <zdg/kernel/render/render_mesh.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace zdg {

namespace {

using V3 = Point3<double>;

V3 normalized(const V3& v) {
  const double n = std::sqrt(dot(v, v));
  return n > 0 ? V3{v.x / n, v.y / n, v.z / n} : V3{0, 0, 1};
}

struct Camera {
  V3 centre, right, up, toward; // toward: from the centre to the camera
  double scale = 1, ox = 0, oy = 0;
};

// The normal of face f (the given one, else Newell's formula on its vertices).
V3 face_normal(const PolygonMesh& m, std::int64_t f) {
  if (!m.face_normals.empty()) return m.face_normals[static_cast<std::size_t>(f)];
  const auto idx = m.face(f);
  V3 n{0, 0, 0};
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const V3& a = m.vertices[static_cast<std::size_t>(idx[k])];
    const V3& b = m.vertices[static_cast<std::size_t>(idx[(k + 1) % idx.size()])];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return normalized(n);
}

} // namespace

RgbImage render_mesh(const PolygonMesh& mesh, const std::string& field,
                     const MeshRenderOptions& opt, MeshRenderReport* report) {
  mesh.validate();
  if (opt.supersample < 1 || opt.supersample > 4)
    throw InvalidArgument("render: supersample " + std::to_string(opt.supersample) + " (1..4)");
  check_picture_size(opt.width, opt.height);
  if (mesh.face_count() >= std::numeric_limits<std::int32_t>::max())
    throw InvalidArgument("render: more than 2^31 - 2 faces");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto& p = mesh.vertices[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidArgument("render: vertex " + std::to_string(i) + " is not finite");
  }
  const std::vector<double>* values = nullptr;
  for (const auto& [name, v] : mesh.face_scalars) {
    if (name == field) values = &v;
  }
  if (!field.empty() && values == nullptr) {
    std::string known;
    for (const auto& [name, v] : mesh.face_scalars) known += (known.empty() ? "" : ", ") + name;
    throw InvalidArgument("render: the mesh has no face field '" + field +
                          "' (fields: " + (known.empty() ? std::string("none") : known) + ")");
  }
  const int S = opt.supersample;
  const bool bar = values != nullptr;
  const int W = opt.width, H = opt.height;
  const int text_scale = std::max(1, std::min(W, H) / 400);
  const int margin = W / 40, top = 16 * text_scale + margin,
            bar_space = bar ? 30 * 6 * text_scale : 0;
  const ColorScale scale = bar ? choose_color_scale(*values, opt.value_min, opt.value_max,
                                                    opt.clip_percent, opt.color_map)
                               : ColorScale{};
  const std::int64_t nv = mesh.vertex_count(), nf = mesh.face_count();
  const unsigned threads = opt.threads;

  // Camera frame: +z up, looking at the centre of the bounding box.
  V3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity()};
  V3 hi{-lo.x, -lo.y, -lo.z};
  for (const auto& p : mesh.vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  Camera cam;
  if (nv > 0) cam.centre = {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
  const double a = opt.azimuth * std::numbers::pi / 180, e = opt.elevation * std::numbers::pi / 180;
  cam.toward = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
  cam.right = normalized(cross(V3{0, 0, 1}, cam.toward));
  if (std::abs(cam.toward.z) > 0.999999) cam.right = {std::sin(a), -std::cos(a), 0}; // from above
  cam.up = cross(cam.toward, cam.right);
  // Vertices in the camera frame (right, up, depth: larger = nearer), then framed: the
  // projected extent fills the drawing area; sample coordinates have y down.
  std::vector<float> px(static_cast<std::size_t>(nv)), py(px.size()), pz(px.size());
  const auto chunks = static_cast<std::int64_t>(worker_count(threads, nv));
  std::vector<std::array<double, 4>> extent(
      static_cast<std::size_t>(std::max<std::int64_t>(chunks, 1)),
      {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
       std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()});
  parallel_for(chunks, static_cast<unsigned>(chunks), [&](std::int64_t k) {
    auto& ext = extent[static_cast<std::size_t>(k)];
    for (std::int64_t i = nv * k / chunks; i < nv * (k + 1) / chunks; ++i) {
      const V3 d = mesh.vertices[static_cast<std::size_t>(i)] - cam.centre;
      const double x = dot(d, cam.right), y = dot(d, cam.up);
      px[static_cast<std::size_t>(i)] = static_cast<float>(x);
      py[static_cast<std::size_t>(i)] = static_cast<float>(y);
      pz[static_cast<std::size_t>(i)] = static_cast<float>(dot(d, cam.toward));
      ext = {std::min(ext[0], x), std::max(ext[1], x), std::min(ext[2], y), std::max(ext[3], y)};
    }
  });
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  if (nv > 0) {
    xmin = ymin = std::numeric_limits<double>::infinity();
    xmax = ymax = -xmin;
    for (const auto& ex : extent) {
      xmin = std::min(xmin, ex[0]);
      xmax = std::max(xmax, ex[1]);
      ymin = std::min(ymin, ex[2]);
      ymax = std::max(ymax, ex[3]);
    }
  }
  const double area_w = (W - 2 * margin - bar_space) * S, area_h = (H - top - margin) * S;
  cam.scale =
      std::min(area_w / std::max(xmax - xmin, 1e-300), area_h / std::max(ymax - ymin, 1e-300));
  if (!std::isfinite(cam.scale) || cam.scale <= 0) cam.scale = 1;
  cam.ox = margin * S + area_w / 2 - cam.scale * (xmin + xmax) / 2;
  cam.oy = top * S + area_h / 2 + cam.scale * (ymin + ymax) / 2;
  parallel_chunks(nv, threads, [&](std::int64_t b, std::int64_t end) {
    for (std::int64_t i = b; i < end; ++i) {
      const auto u = static_cast<std::size_t>(i);
      px[u] = static_cast<float>(cam.ox + cam.scale * px[u]);
      py[u] = static_cast<float>(cam.oy - cam.scale * py[u]);
    }
  });

  // Z-buffer over bands of sample rows, one band per worker.
  const int SW = W * S, SH = H * S;
  std::vector<float> depth(static_cast<std::size_t>(SW) * SH,
                           -std::numeric_limits<float>::infinity());
  std::vector<std::int32_t> face_at(depth.size(), -1);
  const auto bands = static_cast<std::int64_t>(worker_count(threads, SH));
  const auto fs = static_cast<std::size_t>(mesh.face_size);
  parallel_for(bands, static_cast<unsigned>(bands), [&](std::int64_t band) {
    const int y0 = static_cast<int>(SH * band / bands),
              y1 = static_cast<int>(SH * (band + 1) / bands);
    for (std::int64_t f = 0; f < nf; ++f) {
      const std::int64_t* idx = mesh.indices.data() + static_cast<std::size_t>(f) * fs;
      float fy0 = py[static_cast<std::size_t>(idx[0])], fy1 = fy0;
      for (std::size_t k = 1; k < fs; ++k) {
        fy0 = std::min(fy0, py[static_cast<std::size_t>(idx[k])]);
        fy1 = std::max(fy1, py[static_cast<std::size_t>(idx[k])]);
      }
      if (fy1 < static_cast<float>(y0) - 0.5f || fy0 > static_cast<float>(y1) + 0.5f) continue;
      const auto i0 = static_cast<std::size_t>(idx[0]);
      for (std::size_t k = 1; k + 1 < fs; ++k) {
        const auto i1 = static_cast<std::size_t>(idx[k]), i2 = static_cast<std::size_t>(idx[k + 1]);
        const float ax = px[i0], ay = py[i0], bx = px[i1], by = py[i1], cx = px[i2], cy = py[i2];
        const float area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        if (area == 0.0f) continue;
        const float x_lo = std::min({ax, bx, cx}), x_hi = std::max({ax, bx, cx});
        const float y_lo = std::min({ay, by, cy}), y_hi = std::max({ay, by, cy});
        // Off the picture (or not finite: every comparison with NaN is false): skipped, so
        // that the casts below only see values in range.
        if (!(x_hi >= 0.0f && x_lo <= static_cast<float>(SW) && y_hi >= static_cast<float>(y0) &&
              y_lo <= static_cast<float>(y1)))
          continue;
        const int xa = static_cast<int>(std::max(0.0f, std::floor(x_lo)));
        const int xb = static_cast<int>(std::min(static_cast<float>(SW - 1), std::ceil(x_hi)));
        const int ya = static_cast<int>(std::max(static_cast<float>(y0), std::floor(y_lo)));
        const int yb = static_cast<int>(std::min(static_cast<float>(y1 - 1), std::ceil(y_hi)));
        const float inv = 1.0f / area;
        const float za = pz[i0], zb = pz[i1], zc = pz[i2];
        for (int y = ya; y <= yb; ++y) {
          const float sy = static_cast<float>(y) + 0.5f;
          for (int x = xa; x <= xb; ++x) {
            const float sx = static_cast<float>(x) + 0.5f;
            // barycentric weights of (sx, sy): w0 for a, w1 for b, w2 for c
            const float w1 = ((sx - ax) * (cy - ay) - (sy - ay) * (cx - ax)) * inv;
            const float w2 = ((bx - ax) * (sy - ay) - (by - ay) * (sx - ax)) * inv;
            const float w0 = 1.0f - w1 - w2;
            if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
            const float z = w0 * za + w1 * zb + w2 * zc;
            const std::size_t s = static_cast<std::size_t>(y) * SW + static_cast<std::size_t>(x);
            if (z > depth[s]) {
              depth[s] = z;
              face_at[s] = static_cast<std::int32_t>(f);
            }
          }
        }
      }
    }
  });

  // Shading: Lambert, two-sided, light from the camera, a little above and to the left.
  const V3 light = normalized(cam.toward + 0.5 * cam.up - 0.3 * cam.right);
  RgbImage img(W, H);
  std::int64_t covered = 0;
  for (auto id : face_at) covered += id >= 0 ? 1 : 0;
  parallel_chunks(H, threads, [&](std::int64_t r0, std::int64_t r1) {
    for (auto y = static_cast<int>(r0); y < static_cast<int>(r1); ++y) {
      for (int x = 0; x < W; ++x) {
        double r = 0, g = 0, b = 0;
        int hits = 0;
        for (int j = 0; j < S; ++j) {
          for (int i = 0; i < S; ++i) {
            const std::size_t s =
                static_cast<std::size_t>(y * S + j) * SW + static_cast<std::size_t>(x * S + i);
            const std::int32_t f = face_at[s];
            if (f < 0) {
              r += 255;
              g += 255;
              b += 255;
              continue;
            }
            ++hits;
            const double lambert = 0.3 + 0.7 * std::abs(dot(face_normal(mesh, f), light));
            const Rgb c = bar ? scale((*values)[static_cast<std::size_t>(f)]) : Rgb{205, 205, 215};
            r += c.r * lambert;
            g += c.g * lambert;
            b += c.b * lambert;
          }
        }
        if (hits == 0) continue;
        const double n = S * S;
        img.set(x, y,
                {static_cast<std::uint8_t>(std::lround(std::min(255.0, r / n))),
                 static_cast<std::uint8_t>(std::lround(std::min(255.0, g / n))),
                 static_cast<std::uint8_t>(std::lround(std::min(255.0, b / n)))});
      }
    }
  });

  const Rgb ink{20, 20, 20};
  std::string title = opt.title;
  if (title.empty())
    title =
        (field.empty() ? std::string("surface") : field) + " (faces: " + std::to_string(nf) + ")";
  draw_text(img, margin, margin / 2, title, ink, text_scale);
  if (bar) {
    const int bw = 12 * text_scale, bh = (H - top - margin) * 2 / 3;
    const int bx = W - bar_space + 2 * text_scale, by = top + (H - top - margin - bh) / 2;
    draw_color_bar(img, bx, by, bw, bh, scale.map, scale.lo, scale.hi, field, text_scale);
  }
  if (report != nullptr) {
    report->value_min = scale.lo;
    report->value_max = scale.hi;
    report->color_map = scale.map;
    report->faces = nf;
    report->samples = covered;
  }
  return img;
}

MeshRenderReport render_mesh_png(const std::string& path, const PolygonMesh& mesh,
                                 const std::string& field, const MeshRenderOptions& options) {
  MeshRenderReport report;
  const RgbImage img = render_mesh(mesh, field, options, &report);
  write_png(path, img);
  return report;
}

} // namespace zdg
