// Text files of lattice points, parsed from their bytes (so that they can be fuzzed) and read
// from a path.
//
// Point file: one point a line, its coordinates as decimal integers of any size (read by
// parse_integer: "010" is ten) separated by spaces or tabs; '#' starts a comment that runs to
// the end of the line; blank lines are skipped; "\r\n" line ends are accepted. Every point has
// the same number of coordinates, one of the dimensions the caller allows.
//
// Digital path file (zdg dss): the same 2D points, one a line, or a Freeman chain
// "x0 y0 0123..." (kernel/curves/freeman_chain.hpp) on the first data line (three or more fields),
// with nothing after it.
//
// Errors are IoError "SOURCE:LINE: what was wrong" (SOURCE: the name given by the caller, the
// path for read_*). Cost: O(size of the text) plus the integer conversions; memory: the points.
#pragma once

#include <zdg/arith/integer.hpp>
#include <zdg/arith/point.hpp>
#include <zdg/kernel/curves/freeman_chain.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace zdg {

/// Points of a point file: dim coordinates per point, row after row.
struct PointList {
  int dim = 0;
  std::vector<BigInt> coords;     // point k is coords[k * dim .. k * dim + dim)
  std::vector<std::size_t> lines; // the line of each point (1-based)

  std::size_t size() const { return lines.size(); }
};

/// Parses a point file whose points all have one of the dimensions in `dims` (for instance
/// {2, 3}); at least one point. IoError naming source and line otherwise.
PointList parse_point_file(std::string_view text, const std::string& source,
                           const std::vector<int>& dims);
PointList read_point_file(const std::string& path, const std::vector<int>& dims);

/// A digital path: 2D points (one a line) or a Freeman chain.
struct DigitalPathFile {
  std::optional<FreemanChain> chain;  // set when the file is a Freeman chain
  std::size_t chain_line = 0;         // its line
  std::vector<Point2<BigInt>> points; // the points of a point list (empty for a chain)
  std::vector<std::size_t> lines;     // the line of each point
};

DigitalPathFile parse_digital_path_file(std::string_view text, const std::string& source);
DigitalPathFile read_digital_path_file(const std::string& path);

/// The data lines of a text file: each non-blank line, without its '#' comment, split into
/// whitespace-separated fields, with its line number. The tokenizer of the point, path and
/// half-plane files.
struct TextLine {
  std::size_t number = 0;
  std::string_view text; // the line without comment and line end
  std::vector<std::string_view> fields;
};
std::vector<TextLine> data_lines(std::string_view text);

} // namespace zdg
