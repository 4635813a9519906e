#include <zdg/kernel/curves/image_contours.hpp>

#include <zdg/arith/error.hpp>

#include <string>

namespace zdg {

std::int64_t ImageContours::linels() const {
  std::int64_t n = 0;
  for (const auto& c : contours) n += static_cast<std::int64_t>(c.size());
  return n;
}

ImageContours image_contours(const Image<std::uint8_t>& image, int k, int kbar) {
  if (image.dim() != 2)
    throw InvalidArgument("contours need a 2D image (got " + std::to_string(image.dim()) + "-D)");
  if (!((k == 4 && kbar == 8) || (k == 8 && kbar == 4)))
    throw InvalidArgument("adjacency pair (" + std::to_string(k) + "," + std::to_string(kbar) +
                          ") for an image: expected 4,8 or 8,4");
  const bool join = k == 8;
  const std::int64_t ny = image.domain().extent(0), nx = image.domain().extent(1);
  const Pixel lower{image.domain().lower(1), image.domain().lower(0)};
  const std::uint8_t* data = image.values().data();
  auto in = [&](std::int64_t i, std::int64_t j) {
    return i >= 0 && j >= 0 && i < nx && j < ny && data[j * nx + i] != 0;
  };
  // Code c: outer pixel at -y (0), +x (1), +y (2), -x (3) of the inner one; start pointel at
  // inner + (0,0), (1,0), (1,1), (0,1) (kernel/curves/digital_contour.hpp, inner_pixel).
  static constexpr std::int64_t ox[4] = {0, 1, 0, -1}, oy[4] = {-1, 0, 1, 0};
  static constexpr std::int64_t sx[4] = {0, 1, 1, 0}, sy[4] = {0, 0, 1, 1};
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(nx * ny), 0);
  ImageContours out;
  for (std::int64_t j = 0; j < ny; ++j)
    for (std::int64_t i = 0; i < nx; ++i) {
      if (data[j * nx + i] == 0) continue;
      for (int c0 = 0; c0 < 4; ++c0) {
        if (in(i + ox[c0], j + oy[c0]) || (seen[std::size_t(j * nx + i)] >> c0) & 1) continue;
        DigitalContour contour;
        contour.start = {lower.x + i + sx[c0], lower.y + j + sy[c0]};
        std::int64_t pi = i, pj = j; // inner pixel of the current linel
        int c = c0;
        do {
          seen[std::size_t(pj * nx + pi)] |= std::uint8_t(1 << c);
          contour.codes.push_back(static_cast<std::uint8_t>(c));
          // Moving along code c: d = freeman_step(c); ahead of the inner and outer pixels.
          const Pixel d = freeman_step(c);
          const std::int64_t ai = pi + d.x, aj = pj + d.y;     // ahead left
          const std::int64_t bi = ai + ox[c], bj = aj + oy[c]; // ahead right
          const bool left = in(ai, aj), right = in(bi, bj);
          if (right && (left || join)) {
            pi = bi; // turn right: the next linel has the ahead-right pixel inside
            pj = bj;
            c = (c + 3) & 3;
          } else if (left) {
            pi = ai; // straight on
            pj = aj;
          } else {
            c = (c + 1) & 3; // turn left around the same inner pixel
          }
        } while (!(pi == i && pj == j && c == c0));
        (contour.twice_signed_area() > 0 ? out.b0 : out.b1) += 1;
        out.contours.push_back(std::move(contour));
      }
    }
  return out;
}

} // namespace zdg
