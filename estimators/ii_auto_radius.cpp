#include <zdg/arith/error.hpp>
#include <zdg/estimators/ii_auto_radius.hpp>
#include <zdg/kernel/curves/maximal_segments.hpp>

#include <array>
#include <optional>
#include <sstream>
#include <unordered_set>
#include <utility>
#include <vector>

namespace zdg {

namespace {

struct LengthSum {
  double total = 0;
  std::size_t segments = 0, contours = 0;

  void add_contour(const DigitalContour& c) {
    const auto pts = c.pointels();
    if (pts.empty()) return;
    for (const auto& s : maximal_segments_exact(pts, true, Connectivity::four).value) {
      total += static_cast<double>(s.length - 1);
      ++segments;
    }
    ++contours;
  }

  MaximalSegmentLengths result() const {
    MaximalSegmentLengths r;
    r.segments = segments;
    r.contours = contours;
    if (segments > 0) r.mean = total / static_cast<double>(segments);
    return r;
  }
};

// The section of the set by the plane x_axis = level, in the coordinates (u, v) of the axes
// axis + 1 and axis + 2 (cyclic), so that the 2D contours run counter-clockwise seen from
// +e_axis.
class Section : public GaussDigitization2 {
public:
  Section(const VoxelPredicate& inside, const VoxelBox& box, int axis, std::int64_t level)
      : GaussDigitization2(Box2{{coord(box.lo, (axis + 1) % 3), coord(box.lo, (axis + 2) % 3)},
                                {coord(box.hi, (axis + 1) % 3), coord(box.hi, (axis + 2) % 3)}}),
        inside_(inside), axis_(axis), level_(level) {}

  Voxel voxel(const Pixel& z) const {
    Voxel v{0, 0, 0};
    coord(v, axis_) = level_;
    coord(v, (axis_ + 1) % 3) = z.x;
    coord(v, (axis_ + 2) % 3) = z.y;
    return v;
  }

protected:
  bool inside(const Pixel& z) const override { return inside_(voxel(z)); }

private:
  const VoxelPredicate& inside_;
  int axis_;
  std::int64_t level_;
};

Pixel project(const Voxel& v, int axis) {
  return {coord(v, (axis + 1) % 3), coord(v, (axis + 2) % 3)};
}

} // namespace

MaximalSegmentLengths mean_maximal_segment_length(std::span<const DigitalContour> contours) {
  LengthSum sum;
  for (const auto& c : contours) sum.add_contour(c);
  return sum.result();
}

MaximalSegmentLengths mean_slice_maximal_segment_length(const VoxelPredicate& inside,
                                                        const VoxelBox& box,
                                                        std::span<const Surfel> surfels) {
  LengthSum sum;
  for (int axis = 0; axis < 3; ++axis) {
    std::unordered_set<Surfel, SurfelHash> seen;
    for (const auto& s : surfels) {
      const int b = orthogonal_axis(s);
      if (b == axis || seen.count(s) != 0) continue;
      const Voxel in = inner_voxel(s), out = outer_voxel(s);
      Section section(inside, box, axis, coord(in, axis));
      // The linel of s: inner pixel on its left, outer pixel on its right.
      const Pixel pin = project(in, axis), pout = project(out, axis);
      std::optional<std::pair<Pixel, int>> linel;
      for (int code = 0; code < 4 && !linel; ++code) {
        for (const Pixel& p :
             {pin, Pixel{pin.x + 1, pin.y}, Pixel{pin.x, pin.y + 1}, Pixel{pin.x + 1, pin.y + 1}}) {
          if (DigitalContour::inner_pixel(p, code) == pin &&
              DigitalContour::outer_pixel(p, code) == pout) {
            linel = std::pair<Pixel, int>{p, code};
            break;
          }
        }
      }
      if (!linel) throw Error("slice contours: internal error, no linel for a surfel");
      const DigitalContour c = track_contour(section, linel->first, linel->second);
      bool clipped = false;
      Pixel p = c.start;
      for (auto code : c.codes) {
        const Voxel vin = section.voxel(DigitalContour::inner_pixel(p, code));
        const Voxel vout = section.voxel(DigitalContour::outer_pixel(p, code));
        int a = 0;
        while (coord(vin, a) == coord(vout, a)) ++a;
        seen.insert(surfel_between(vin, a, coord(vout, a) > coord(vin, a) ? 1 : -1));
        clipped = clipped || !box.contains(vout);
        const Pixel d = freeman_step(code);
        p = Pixel{p.x + d.x, p.y + d.y};
      }
      if (!clipped) sum.add_contour(c);
    }
  }
  return sum.result();
}

double ii_auto_radius(const MaximalSegmentLengths& lengths, double k, double h) {
  if (!(k > 0) || !(h > 0)) {
    std::ostringstream msg;
    msg << "parameter-free II radius: k and h must be positive (got k = " << k << ", h = " << h
        << ")";
    throw InvalidArgument(msg.str());
  }
  if (lengths.segments == 0 || !(lengths.mean > 0)) {
    throw InvalidArgument("parameter-free II radius: the digitization has no maximal segment of "
                          "positive length (empty or degenerate boundary)");
  }
  return k * lengths.mean * lengths.mean * h;
}

} // namespace zdg
