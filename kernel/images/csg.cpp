#include <zdg/kernel/images/csg.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

namespace zdg {

namespace {

std::string shape_text(const Domain& d) {
  std::string s = "(";
  for (int k = 0; k < d.dim(); ++k) {
    if (k) s += ", ";
    s += std::to_string(d.extent(k));
  }
  s += ")";
  bool origin = true;
  for (int k = 0; k < d.dim(); ++k) origin = origin && d.lower(k) == 0;
  if (!origin) {
    s += " at (";
    for (int k = 0; k < d.dim(); ++k) {
      if (k) s += ", ";
      s += std::to_string(d.lower(k));
    }
    s += ")";
  }
  return s;
}

} // namespace

std::string csg_name(CsgOperation op) {
  switch (op) {
  case CsgOperation::union_of:
    return "union";
  case CsgOperation::intersection:
    return "intersection";
  case CsgOperation::difference:
    return "difference";
  case CsgOperation::symmetric_difference:
    return "symmetric-difference";
  }
  return "?";
}

Image<std::uint8_t> csg(CsgOperation op, const Image<std::uint8_t>& a, const Image<std::uint8_t>& b,
                        unsigned threads) {
  if (!(a.domain() == b.domain())) {
    throw InvalidArgument("csg " + csg_name(op) + ": the images differ in shape: " +
                          shape_text(a.domain()) + " and " + shape_text(b.domain()));
  }
  Image<std::uint8_t> out(a.domain());
  const std::uint8_t* x = a.values().data();
  const std::uint8_t* y = b.values().data();
  std::uint8_t* z = out.values().data();
  parallel_chunks(a.size(), threads, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      const bool p = x[i] != 0, q = y[i] != 0;
      bool r = false;
      switch (op) {
      case CsgOperation::union_of:
        r = p || q;
        break;
      case CsgOperation::intersection:
        r = p && q;
        break;
      case CsgOperation::difference:
        r = p && !q;
        break;
      case CsgOperation::symmetric_difference:
        r = p != q;
        break;
      }
      z[i] = r ? 1 : 0;
    }
  });
  return out;
}

Image<std::uint8_t> csg_complement(const Image<std::uint8_t>& a, unsigned threads) {
  Image<std::uint8_t> out(a.domain());
  const std::uint8_t* x = a.values().data();
  std::uint8_t* z = out.values().data();
  parallel_chunks(a.size(), threads, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) z[i] = x[i] != 0 ? 0 : 1;
  });
  return out;
}

} // namespace zdg
