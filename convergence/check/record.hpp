// The values a property campaign handles (zdg check, convergence/check/property.hpp): a test
// case, a request sent to an external command, an answer. A record is an ordered list of named
// fields, each an exact integer (BigInt), a boolean, a text, a list of texts, or an array of
// integers of any rank (a list, a list of points, an image), so that one representation serves
// the generators, the shrinker, the oracles and the line-JSON protocol:
//
//   {"n":"5","m":"7","a":"-3","b":"12"}               four integers (as decimal strings)
//   {"points":[["0","0"],["1","1"]],"connectivity":"8"} a path and an integer
//   {"image":[[0,1],[1,1]]}                            an image (small values as numbers)
//   {"segments":[{"begin":0,"end":3,"a":"1","b":"2","mu":"0"}]}  rows as objects (columns)
//
// Shrinking (Hughes and Claessen's QuickCheck, ICFP 2000; Hypothesis' greedy reduction): each
// field says how it may be simplified, shrink_candidates() lists the simpler records in the
// order they are tried (structure before values: shorter paths, smaller images, then values
// moved towards 0 by halving the distance, O(log |v|) candidates per integer). The campaign
// keeps the first candidate that is still valid and still fails, and starts again from it: a
// greedy descent to a local minimum. A candidate never has more points or larger magnitudes
// than its parent, so the descent ends.
//
// JSON text (to_json): integers as decimal strings (they may exceed 64 bits), except arrays
// marked `numbers` (0/1 images, distances of small images), written as JSON numbers.
#pragma once

#include <zdg/arith/integer.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace zdg::check {

enum class FieldKind { integer, boolean, text, texts, array };

/// How a field may be simplified by the shrinker.
enum class Shrink {
  none,        // never changed
  toward_zero, // integer (or every entry of an array): moved towards 0
  path,        // array {n, d} of consecutive points: drop the first or last points, translate
               // the path towards the origin
  list,        // array {n} or {n, k}: drop entries, move the values towards 0
  image        // array of rank 2 or 3: drop border slices, clear nonzero values
};

struct Field {
  std::string name;
  FieldKind kind = FieldKind::integer;
  std::vector<BigInt> ints;       // integer: one value; array: the entries, row-major
  std::vector<std::size_t> shape; // array: the extents
  std::vector<std::string> texts; // text: one; texts: several
  bool flag = false;              // boolean
  bool numbers = false;           // array written as JSON numbers instead of strings
  Shrink shrink = Shrink::none;
  /// A rank-2 array {n, k} written as a list of n objects with these k keys (e.g. the segments
  /// {"begin","end","a","b","mu"} of a tangential cover); empty: nested lists.
  std::vector<std::string> columns;
  /// In an oracle's answer: a field the property's judge checks (any of several right answers
  /// is accepted: a nearest site among ties, a skeleton), not compared by equality; its value is
  /// a reference for the judge and the report.
  bool judged = false;
};

class Record {
public:
  std::vector<Field> fields;

  Record& integer(std::string name, BigInt v, Shrink s = Shrink::none);
  Record& boolean(std::string name, bool v);
  Record& text(std::string name, std::string v);
  Record& texts(std::string name, std::vector<std::string> v);
  Record& array(std::string name, std::vector<std::size_t> shape, std::vector<BigInt> values,
                Shrink s = Shrink::none, bool numbers = false);

  bool has(const std::string& name) const;
  /// The field of that name; InvalidArgument when absent.
  const Field& at(const std::string& name) const;
  Field& at(const std::string& name);
  const BigInt& int_of(const std::string& name) const;
  /// The integer as int64 (InvalidArgument when it does not fit).
  std::int64_t i64_of(const std::string& name) const;

  friend bool operator==(const Record&, const Record&) = default;
};

bool operator==(const Field& a, const Field& b);

/// One line of compact JSON (see the header comment).
std::string to_json(const Record& r);
std::string to_json(const Field& f); // the value only

/// Simpler records, in the order the shrinker tries them.
std::vector<Record> shrink_candidates(const Record& r);

/// Values strictly simpler than v on the way to 0: 0, -v (for v < 0), sign(v), v/2, then
/// v - v/2, v - v/4, ..., v - sign(v) (the binary search of the smallest failing magnitude).
std::vector<BigInt> integer_shrinks(const BigInt& v);

/// Number of entries of an array of that shape.
std::size_t shape_size(const std::vector<std::size_t>& shape);

} // namespace zdg::check
