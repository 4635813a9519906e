#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/cycles_ply.hpp>

#include <fstream>
#include <map>
#include <sstream>

namespace zdg {

void write_cycles_ply(const std::string& path, const HomologyGenerators& g,
                      const std::vector<std::int64_t>& lower) {
  const int d = g.dim;
  std::map<std::array<std::int64_t, 3>, std::int64_t> vertex;
  std::vector<std::array<std::int64_t, 3>> vertices;
  const auto vid = [&](const std::array<std::int64_t, 3>& x) {
    const auto [it, fresh] = vertex.emplace(x, static_cast<std::int64_t>(vertices.size()));
    if (fresh) vertices.push_back(x);
    return it->second;
  };
  std::ostringstream points, edges, faces;
  std::int64_t n_points = 0, n_edges = 0, n_faces = 0, cycle = 0;
  for (std::size_t k = 0; k < g.generators.size(); ++k) {
    for (const auto& chain : g.generators[k]) {
      for (const auto& x : chain) {
        std::vector<std::size_t> odd;
        for (std::size_t a = 0; a < 3; ++a) {
          if (x[a] % 2 != 0) odd.push_back(a);
        }
        if (odd.empty()) {
          points << vid(x) << ' ' << cycle << '\n';
          ++n_points;
        } else if (odd.size() == 1) {
          auto a = x, b = x;
          a[odd[0]] -= 1;
          b[odd[0]] += 1;
          edges << vid(a) << ' ' << vid(b) << ' ' << cycle << '\n';
          ++n_edges;
        } else {
          const int s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
          faces << 4;
          for (const auto& c : s) {
            auto y = x;
            y[odd[0]] += c[0];
            y[odd[1]] += c[1];
            faces << ' ' << vid(y);
          }
          faces << ' ' << cycle << '\n';
          ++n_faces;
        }
      }
      ++cycle;
    }
  }
  std::ofstream out(path);
  if (!out) throw IoError(path + ": cannot write");
  out << "ply\nformat ascii 1.0\ncomment zdg homology generators\ncomment betti";
  for (const auto& gens : g.generators) out << ' ' << gens.size();
  out << "\nelement vertex " << vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element point " << n_points << "\nproperty int vertex\nproperty int cycle\n"
      << "element edge " << n_edges
      << "\nproperty int vertex1\nproperty int vertex2\nproperty int cycle\n"
      << "element face " << n_faces
      << "\nproperty list uchar int vertex_indices\nproperty int cycle\nend_header\n";
  for (const auto& x : vertices) {
    // Khalimsky coordinate c on axis k: lattice coordinate lower_k + (c - 1) / 2.
    double p[3] = {0, 0, 0};
    for (int k = 0; k < d; ++k) {
      p[k] = static_cast<double>(lower[static_cast<std::size_t>(k)]) +
             (static_cast<double>(x[static_cast<std::size_t>(k)]) - 1) / 2;
    }
    if (d == 3) {
      out << p[2] << ' ' << p[1] << ' ' << p[0] << '\n';
    } else {
      out << p[1] << ' ' << p[0] << " 0\n";
    }
  }
  out << points.str() << edges.str() << faces.str();
  if (!out.flush()) throw IoError(path + ": write failed");
}

} // namespace zdg
