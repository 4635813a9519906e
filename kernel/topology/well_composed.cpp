#include <zdg/kernel/topology/well_composed.hpp>

#include <zdg/arith/error.hpp>

namespace zdg {

WellComposedness well_composedness(const Image<std::uint8_t>& image) {
  const Domain& d = image.domain();
  const int dim = d.dim();
  if (dim != 2 && dim != 3) {
    throw InvalidArgument("well-composedness: a " + std::to_string(dim) +
                          "D image (2D or 3D only)");
  }
  WellComposedness out;
  const std::uint8_t* v = image.values().data();
  auto in = [&](std::int64_t i) { return v[i] != 0; };
  auto fail = [&](std::int64_t i, std::string what) {
    out.well_composed = false;
    out.corner = d.point(i);
    out.configuration = std::move(what);
  };
  // C1 in every pair of axes (i < j): the square {p, p + e_i, p + e_j, p + e_i + e_j}. The
  // points are walked as (z, y, x) with z of extent 1 in 2D.
  const int off = 3 - dim;
  std::int64_t ext[3] = {1, 1, 1}, str[3] = {0, 0, 0};
  for (int k = 0; k < dim; ++k) {
    ext[k + off] = d.extent(k);
    str[k + off] = d.stride(k);
  }
  for (int i = 0; i < dim && out.well_composed; ++i) {
    for (int j = i + 1; j < dim && out.well_composed; ++j) {
      const int ii = i + off, jj = j + off;
      const std::int64_t si = str[ii], sj = str[jj];
      std::int64_t c[3];
      for (c[0] = 0; c[0] < ext[0] && out.well_composed; ++c[0]) {
        for (c[1] = 0; c[1] < ext[1] && out.well_composed; ++c[1]) {
          for (c[2] = 0; c[2] < ext[2]; ++c[2]) {
            if (c[ii] + 1 == ext[ii] || c[jj] + 1 == ext[jj]) continue;
            const std::int64_t p = c[0] * str[0] + c[1] * str[1] + c[2] * str[2];
            const bool a = in(p), b = in(p + si), e = in(p + sj), f = in(p + si + sj);
            if (a == f && b == e && a != b) {
              fail(p, "C1 axes (" + std::to_string(i) + ", " + std::to_string(j) + ")");
              break;
            }
          }
        }
      }
    }
  }
  if (dim == 3 && out.well_composed) {
    const std::int64_t s0 = d.stride(0), s1 = d.stride(1);
    for (std::int64_t z = 0; z + 1 < d.extent(0) && out.well_composed; ++z) {
      for (std::int64_t y = 0; y + 1 < d.extent(1) && out.well_composed; ++y) {
        for (std::int64_t x = 0; x + 1 < d.extent(2); ++x) {
          const std::int64_t p = z * s0 + y * s1 + x;
          unsigned bits = 0;
          for (unsigned c = 0; c < 8; ++c) {
            const std::int64_t q = p + ((c >> 2) & 1) * s0 + ((c >> 1) & 1) * s1 + (c & 1);
            bits |= static_cast<unsigned>(in(q)) << c;
          }
          // Antipodal pairs are {c, 7 - c}.
          bool critical = false;
          for (unsigned c = 0; c < 4; ++c) {
            const unsigned pair = (1u << c) | (1u << (7 - c));
            critical = critical || bits == pair || bits == (0xffu & ~pair);
          }
          if (critical) {
            fail(p, "C2");
            break;
          }
        }
      }
    }
  }
  return out;
}

} // namespace zdg
