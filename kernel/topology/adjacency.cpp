#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <cstdlib>

namespace zdg {

bool is_adjacency(int dim, int k) {
  if (dim == 2) return k == 4 || k == 8;
  if (dim == 3) return k == 6 || k == 18 || k == 26;
  return false;
}

int adjacency_max_l1(int dim, int k) {
  if (!is_adjacency(dim, k)) {
    throw InvalidArgument("adjacency: " + std::to_string(k) + " is not an adjacency of dimension " +
                          std::to_string(dim) + (dim == 3 ? " (6, 18, 26)" : " (4, 8)"));
  }
  switch (k) {
  case 4:
  case 6:
    return 1;
  case 8:
  case 18:
    return 2;
  default:
    return 3;
  }
}

bool is_adjacency_pair(int dim, int object, int background) {
  if (dim == 2) return (object == 8 && background == 4) || (object == 4 && background == 8);
  if (dim == 3) {
    return (object == 6 && (background == 26 || background == 18)) ||
           (background == 6 && (object == 26 || object == 18));
  }
  return false;
}

AdjacencyPair make_adjacency_pair(int dim, int object, int background) {
  if (!is_adjacency_pair(dim, object, background)) {
    throw InvalidArgument(
        "adjacency pair " + std::to_string(object) + "," + std::to_string(background) +
        " is not admissible in dimension " + std::to_string(dim) +
        (dim == 3 ? " (26,6 6,26 18,6 6,18)" : (dim == 2 ? " (8,4 4,8)" : " (only 2D and 3D)")));
  }
  return {dim, object, background};
}

AdjacencyPair default_adjacency_pair(int dim) {
  if (dim == 2) return {2, 8, 4};
  if (dim == 3) return {3, 26, 6};
  throw InvalidArgument("adjacency pair: dimension " + std::to_string(dim) + " is not 2 or 3");
}

namespace {
// A non-negative decimal number of at most 3 digits between spaces; -1 when malformed.
int parse_small(const std::string& s) {
  std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  if (b == std::string::npos) return -1;
  std::string d = s.substr(b, e - b + 1);
  if (d.empty() || d.size() > 3) return -1;
  int v = 0;
  for (char c : d) {
    if (c < '0' || c > '9') return -1;
    v = 10 * v + (c - '0');
  }
  return v;
}
} // namespace

AdjacencyPair parse_adjacency_pair(const std::string& text, int dim) {
  const std::size_t comma = text.find(',');
  int k = -1, kbar = -1;
  if (comma != std::string::npos) {
    k = parse_small(text.substr(0, comma));
    kbar = parse_small(text.substr(comma + 1));
  }
  if (k < 0 || kbar < 0) {
    throw InvalidArgument("adjacency pair '" + text + "' is not K,KBAR (for example 26,6)");
  }
  return make_adjacency_pair(dim, k, kbar);
}

std::vector<std::array<int, 3>> neighbour_offsets(int dim, int k) {
  const int m = adjacency_max_l1(dim, k);
  std::vector<std::array<int, 3>> out;
  const int r2 = dim == 3 ? 1 : 0;
  for (int a = -1; a <= 1; ++a) {
    for (int b = -1; b <= 1; ++b) {
      for (int c = -r2; c <= r2; ++c) {
        const int l1 = std::abs(a) + std::abs(b) + std::abs(c);
        if (l1 == 0 || l1 > m) continue;
        out.push_back({a, b, c});
      }
    }
  }
  return out;
}

} // namespace zdg
