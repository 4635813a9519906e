// Test support for digital topology: random small binary images (RapidCheck, inside a
// property) and the digitizations with known topology (ball, solid torus, hollow sphere,
// disc, annulus) on int64 predicates.
#pragma once

#include <zdg/kernel/images/image.hpp>

#include <rapidcheck.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace zdg::test {

/// Inside a RapidCheck property: a binary image of dimension dim with extents in
/// [1, max_extent], each point in the object with a random density in [10%, 90%]; values
/// other than 1 appear too (nonzero = object).
inline Image<std::uint8_t> random_binary_image(int dim, int max_extent) {
  std::vector<std::int64_t> ext;
  std::int64_t n = 1;
  for (int k = 0; k < dim; ++k) {
    ext.push_back(*rc::gen::inRange<std::int64_t>(1, max_extent + 1));
    n *= ext.back();
  }
  const int density = *rc::gen::inRange(10, 91);
  const auto draws =
      *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n), rc::gen::inRange(0, 100));
  Image<std::uint8_t> img{Domain(ext)};
  for (std::int64_t i = 0; i < n; ++i) {
    const int r = draws[static_cast<std::size_t>(i)];
    img[i] = r < density ? static_cast<std::uint8_t>(1 + r % 3) : 0;
  }
  return img;
}

/// The image of extents `ext` whose points p satisfy pred(c), with c_k = 2 p_k - (ext_k - 1):
/// twice the coordinates relative to the centre of the box (even integers for odd extents).
inline Image<std::uint8_t>
image_from(std::vector<std::int64_t> ext,
           const std::function<bool(const std::vector<std::int64_t>&)>& pred) {
  Domain dom(ext);
  Image<std::uint8_t> img(dom, std::uint8_t{0});
  std::vector<std::int64_t> c(ext.size());
  for (std::int64_t i = 0; i < dom.size(); ++i) {
    auto p = dom.point(i);
    for (std::size_t k = 0; k < ext.size(); ++k) c[k] = 2 * p[k] - (ext[k] - 1);
    img[i] = pred(c) ? 1 : 0;
  }
  return img;
}

/// The digital ball |x|^2 <= r2 centred in the cube of side 2 r + 3 (r >= sqrt(r2)).
inline Image<std::uint8_t> ball_image(std::int64_t r, std::int64_t r2) {
  const std::int64_t n = 2 * r + 3;
  return image_from({n, n, n}, [=](const std::vector<std::int64_t>& c) {
    return c[0] * c[0] + c[1] * c[1] + c[2] * c[2] <= 4 * r2;
  });
}

/// The hollow sphere r_in2 < |x|^2 <= r_out2 (side 2 r + 3).
inline Image<std::uint8_t> hollow_sphere_image(std::int64_t r, std::int64_t r_in2,
                                               std::int64_t r_out2) {
  const std::int64_t n = 2 * r + 3;
  return image_from({n, n, n}, [=](const std::vector<std::int64_t>& c) {
    const std::int64_t s = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    return 4 * r_in2 < s && s <= 4 * r_out2;
  });
}

/// The solid torus (sqrt(x^2 + y^2) - R)^2 + z^2 <= r^2 around axis 0 (x, y on axes 1, 2),
/// decided exactly: with q = x^2 + y^2 and s = q + R^2 + z^2 - r^2, it is s <= 2 R sqrt(q),
/// i.e. s <= 0 or s^2 <= 4 R^2 q.
inline Image<std::uint8_t> torus_image(std::int64_t big_r, std::int64_t small_r) {
  const std::int64_t n = 2 * (big_r + small_r) + 3, m = 2 * small_r + 3;
  return image_from({m, n, n}, [=](const std::vector<std::int64_t>& c) {
    // Doubled coordinates: work with 2R and 2r.
    const std::int64_t z = c[0], x = c[1], y = c[2], R = 2 * big_r, r = 2 * small_r;
    const std::int64_t q = x * x + y * y, s = q + R * R + z * z - r * r;
    return s <= 0 || s * s <= 4 * R * R * q;
  });
}

/// The 2D annulus r_in2 < |x|^2 <= r_out2 and the disc (r_in2 = -1).
inline Image<std::uint8_t> annulus_image(std::int64_t r, std::int64_t r_in2, std::int64_t r_out2) {
  const std::int64_t n = 2 * r + 3;
  return image_from({n, n}, [=](const std::vector<std::int64_t>& c) {
    const std::int64_t s = c[0] * c[0] + c[1] * c[1];
    return 4 * r_in2 < s && s <= 4 * r_out2;
  });
}

/// The image with one more layer of background around it, complemented: the background of
/// the image (the outside included, up to homotopy) as the object of a binary image.
inline Image<std::uint8_t> padded_complement(const Image<std::uint8_t>& img) {
  const Domain& d = img.domain();
  std::vector<std::int64_t> ext;
  for (int k = 0; k < d.dim(); ++k) ext.push_back(d.extent(k) + 2);
  Image<std::uint8_t> out{Domain(ext), std::uint8_t{1}};
  for (std::int64_t i = 0; i < d.size(); ++i) {
    auto p = d.point(i);
    for (auto& v : p) ++v;
    out.at(p) = img[i] != 0 ? 0 : 1;
  }
  return out;
}

/// Copies `part` into `scene` at the offset o (same dimension).
inline void paste(Image<std::uint8_t>& scene, const Image<std::uint8_t>& part,
                  const std::vector<std::int64_t>& o) {
  const Domain& d = part.domain();
  for (std::int64_t i = 0; i < d.size(); ++i) {
    auto p = d.point(i);
    for (std::size_t k = 0; k < p.size(); ++k) p[k] += o[k];
    scene.at(p) = part[i];
  }
}

} // namespace zdg::test
