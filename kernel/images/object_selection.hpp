// The object of a scalar volume: the binary mask { p : value(p) satisfies the rule },
// complemented when `invert` is set.
//
//   nonzero    value != 0          (the default: a binary .vol, a label image)
//   at_least   value >= low        (--threshold T)
//   range      low <= value <= high (--range LO:HI, both ends included)
//   equal      value == low        (--label L)
//
// The value is the physical one (kernel/images/scalar_volume.hpp). Comparisons are exact: on stored
// integers (unscaled) the double bound is compared with the integer exactly, whatever the
// width (int64 and uint64 included, through 128-bit integers); on floats and on scaled values
// (slope * stored + inter, computed in double as NIfTI defines it) the comparison is the IEEE
// one. NaN satisfies no rule (so it is background, or object when inverted).
// Cost: one pass over the voxels, 8- and 16-bit types through a lookup table of the rule;
// parallel over `threads` (0: all cores) through kernel/parallel/parallel_for.hpp.
#pragma once

#include <zdg/kernel/images/image.hpp>
#include <zdg/kernel/images/scalar_volume.hpp>

#include <cstdint>
#include <string>

namespace zdg {

struct ObjectSelection {
  enum class Rule { nonzero, at_least, range, equal };
  Rule rule = Rule::nonzero;
  double low = 0.0, high = 0.0;
  bool invert = false;

  /// "value != 0", "value >= 128", "10 <= value <= 20", "value == 3", "not (...)".
  std::string describe() const;
  /// Whether a physical value is selected (invert applied).
  bool selects(double value) const;
};

struct SelectedObject {
  Image<std::uint8_t> mask; ///< 1 on the object, 0 elsewhere; the volume's domain
  std::int64_t voxels = 0;  ///< number of object voxels
  double min_value = 0.0;   ///< smallest physical value (NaN ignored; NaN if all NaN)
  double max_value = 0.0;   ///< largest physical value
};

/// The object of `volume` under `selection` (the volume's invariants are checked first).
/// A selection of no voxel is not an error here (the command line reports it).
SelectedObject select_object(const ScalarVolume& volume, const ObjectSelection& selection,
                             unsigned threads = 0);

} // namespace zdg
