// Fuzz target: parse_adjacency_pair (kernel/topology/adjacency.hpp) on arbitrary text, in 2D and
// 3D. Either a pair comes back, admissible and printed back to itself, or InvalidArgument.
#include <zdg/arith/error.hpp>
#include <zdg/kernel/topology/adjacency.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (int dim : {2, 3}) {
    try {
      const zdg::AdjacencyPair p = zdg::parse_adjacency_pair(text, dim);
      if (!zdg::is_adjacency_pair(dim, p.object, p.background)) std::abort();
      if (!(zdg::parse_adjacency_pair(p.name(), dim) == p)) std::abort();
    } catch (const zdg::InvalidArgument&) {
    }
  }
  return 0;
}
