#include <zdg/arith/error.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/topology/critical_kernel_thinning.hpp>

#include <algorithm>
#include <array>
#include <bit>

namespace zdg {
namespace {

constexpr std::uint8_t kObject = 1, kActive = 2, kAnchor = 4, kSimple = 8, kKept = 16;

// The 26 faces of the unit cube of the centre point x of a 3x3x3 neighbourhood, in local
// Khalimsky coordinates k in {2, 3, 4}^3 (the point at local position v in {0, 1, 2}^3 is the
// cell 2 v + 1; x is (3, 3, 3)). Points are bits v0 * 9 + v1 * 3 + v2 of a 27-bit mask.
struct Face {
  int dim = 0;
  std::uint32_t incident = 0;            // points whose closed cube contains the face
  std::array<std::uint32_t, 6> coface{}; // incident sets of the faces of dimension dim + 1
  int cofaces = 0;                       // containing it (the neighbourhood holds them all)
  std::array<int, 4> edge{};             // square: its 4 edges; edge: its 2 vertices
  int edges = 0;
  std::array<int, 4> vertex{}; // square: its 4 vertices
  int vertices = 0;
};

struct FaceTable {
  std::array<Face, 26> face;
  std::array<int, 125> id{};              // local cell (k0 * 25 + k1 * 5 + k2) -> face, or -1
  std::array<std::vector<int>, 3> of_dim; // the faces of dimension 0, 1, 2

  static std::uint32_t incident(int k0, int k1, int k2) {
    auto choices = [](int k) {
      return (k % 2 != 0) ? std::array<int, 2>{(k - 1) / 2, -1}
                          : std::array<int, 2>{k / 2 - 1, k / 2};
    };
    std::uint32_t m = 0;
    for (int a : choices(k0)) {
      for (int b : choices(k1)) {
        for (int c : choices(k2)) {
          if (a >= 0 && b >= 0 && c >= 0) m |= std::uint32_t{1} << (a * 9 + b * 3 + c);
        }
      }
    }
    return m;
  }

  FaceTable() {
    id.fill(-1);
    int n = 0;
    for (int k0 = 2; k0 <= 4; ++k0) {
      for (int k1 = 2; k1 <= 4; ++k1) {
        for (int k2 = 2; k2 <= 4; ++k2) {
          if (k0 == 3 && k1 == 3 && k2 == 3) continue;
          id[static_cast<std::size_t>(k0 * 25 + k1 * 5 + k2)] = n++;
        }
      }
    }
    for (int k0 = 2; k0 <= 4; ++k0) {
      for (int k1 = 2; k1 <= 4; ++k1) {
        for (int k2 = 2; k2 <= 4; ++k2) {
          const int i = id[static_cast<std::size_t>(k0 * 25 + k1 * 5 + k2)];
          if (i < 0) continue;
          Face& f = face[static_cast<std::size_t>(i)];
          const std::array<int, 3> k{k0, k1, k2};
          f.dim = (k0 % 2) + (k1 % 2) + (k2 % 2);
          of_dim[static_cast<std::size_t>(f.dim)].push_back(i);
          f.incident = incident(k0, k1, k2);
          for (int a = 0; a < 3; ++a) {
            for (int s : {-1, 1}) {
              auto g = k;
              g[static_cast<std::size_t>(a)] += s;
              if (k[static_cast<std::size_t>(a)] % 2 == 0) {
                f.coface[static_cast<std::size_t>(f.cofaces++)] = incident(g[0], g[1], g[2]);
              }
            }
          }
          // Sub-faces through the odd coordinates (faces of the centre cube).
          std::array<int, 3> odd{};
          int nodd = 0;
          for (int a = 0; a < 3; ++a) {
            if (k[static_cast<std::size_t>(a)] % 2 != 0) odd[static_cast<std::size_t>(nodd++)] = a;
          }
          auto face_id = [&](const std::array<int, 3>& g) {
            return id[static_cast<std::size_t>(g[0] * 25 + g[1] * 5 + g[2])];
          };
          if (f.dim == 1) {
            for (int s : {-1, 1}) {
              auto g = k;
              g[static_cast<std::size_t>(odd[0])] += s;
              f.edge[static_cast<std::size_t>(f.edges++)] = face_id(g);
            }
          } else if (f.dim == 2) {
            for (int t = 0; t < 2; ++t) {
              for (int s : {-1, 1}) {
                auto g = k;
                g[static_cast<std::size_t>(odd[static_cast<std::size_t>(t)])] += s;
                f.edge[static_cast<std::size_t>(f.edges++)] = face_id(g);
              }
            }
            for (int s : {-1, 1}) {
              for (int u : {-1, 1}) {
                auto g = k;
                g[static_cast<std::size_t>(odd[0])] += s;
                g[static_cast<std::size_t>(odd[1])] += u;
                f.vertex[static_cast<std::size_t>(f.vertices++)] = face_id(g);
              }
            }
          }
        }
      }
    }
  }

  static const FaceTable& get() {
    static const FaceTable t;
    return t;
  }
};

// Is face i of the centre's cube essential for the object n (27-bit neighbourhood)?
bool essential(const FaceTable& t, std::uint32_t n, int i) {
  const Face& f = t.face[static_cast<std::size_t>(i)];
  const std::uint32_t clique = n & f.incident;
  if (clique == 0) return false;
  for (int c = 0; c < f.cofaces; ++c) {
    if ((clique & ~f.coface[static_cast<std::size_t>(c)]) == 0) return false;
  }
  return true;
}

// Is face i critical (essential, and its core not contractible), as in the header?
bool critical_face(std::uint32_t n, int i) {
  const FaceTable& t = FaceTable::get();
  if (!essential(t, n, i)) return false;
  const Face& f = t.face[static_cast<std::size_t>(i)];
  if (f.dim == 0) return true; // empty core
  if (f.dim == 1) {
    return (essential(t, n, f.edge[0]) ? 1 : 0) + (essential(t, n, f.edge[1]) ? 1 : 0) != 1;
  }
  // A square: its core on the boundary circle has the essential vertices, the essential
  // edges and their ends; it is one arc iff |V| - |E| = 1 with |E| < 4.
  std::uint32_t vertices = 0;
  int edges = 0;
  for (int v = 0; v < 4; ++v) {
    const int vi = f.vertex[static_cast<std::size_t>(v)];
    if (essential(t, n, vi)) vertices |= 1u << vi;
  }
  for (int e = 0; e < 4; ++e) {
    const int ei = f.edge[static_cast<std::size_t>(e)];
    if (!essential(t, n, ei)) continue;
    ++edges;
    const Face& edge = t.face[static_cast<std::size_t>(ei)];
    vertices |= 1u << edge.edge[0];
    vertices |= 1u << edge.edge[1];
  }
  return !(edges < 4 && std::popcount(vertices) - edges == 1);
}

// floor(n k / w) without forming n k.
std::int64_t chunk_bound(std::int64_t n, std::int64_t k, std::int64_t w) {
  return n / w * k + n % w * k / w;
}

} // namespace

ThinningResult critical_kernel_thinning(const Image<std::uint8_t>& image,
                                        const ThinningOptions& options) {
  const AdjacencyPair pair = detail::resolve_pair(image, options);
  if (!(pair.object == 26 || pair.object == 8)) {
    throw InvalidArgument("critical-kernel thinning works on the cubical complex of the pair " +
                          std::string(pair.dim == 3 ? "26,6" : "8,4") + ", not " + pair.name());
  }
  detail::PaddedVolume vol(image);
  detail::mark_anchors(image, options, vol);
  std::int64_t remaining = 0;
  for (std::uint8_t f : vol.flags) remaining += f & kObject;
  const detail::SimplicityTest simple(pair, remaining >= (std::int64_t{1} << 22));
  const bool conditional =
      options.skeleton == SkeletonKind::curve || options.skeleton == SkeletonKind::surface;
  // The 27 offsets of the 3x3x3 neighbourhood (the slab's empty layers in 2D), and the six
  // face neighbours (four in 2D).
  std::array<std::int64_t, 27> off27{};
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      for (int c = 0; c < 3; ++c) {
        off27[static_cast<std::size_t>(a * 9 + b * 3 + c)] =
            ((a - 1) * vol.extent[1] + (b - 1)) * vol.extent[2] + (c - 1);
      }
    }
  }
  std::vector<std::int64_t> face_offsets = {-vol.extent[1] * vol.extent[2],
                                            vol.extent[1] * vol.extent[2],
                                            -vol.extent[2],
                                            vol.extent[2],
                                            -1,
                                            1};
  if (vol.dim() == 2) face_offsets.erase(face_offsets.begin(), face_offsets.begin() + 2);
  auto flag = [&](std::int64_t p) -> std::uint8_t& {
    return vol.flags[static_cast<std::size_t>(p)];
  };

  // The points to examine in the next pass; at first the border: object points, not anchors,
  // with a face neighbour in the background (the others are not simple).
  std::vector<std::int64_t> active;
  for (std::int64_t p = 0; p < vol.size(); ++p) {
    if ((flag(p) & (kObject | kAnchor)) != kObject) continue;
    for (std::int64_t o : face_offsets) {
      if ((flag(p + o) & kObject) == 0) {
        active.push_back(p);
        flag(p) |= kActive;
        break;
      }
    }
  }

  const unsigned threads = options.threads;
  const int neighbours = vol.dim() == 3 ? 26 : 8;
  ThinningResult result;
  for (;;) {
    // 1. Verdicts on the active points, from the object at the start of the pass.
    std::vector<std::uint8_t> verdict(active.size(), 0); // 1 simple, 2 skeleton point
    parallel_chunks(
        static_cast<std::int64_t>(active.size()), threads, [&](std::int64_t b, std::int64_t e) {
          for (std::int64_t i = b; i < e; ++i) {
            const std::uint32_t c = vol.configuration(active[static_cast<std::size_t>(i)]);
            if (conditional && detail::is_skeleton_point(options.skeleton, pair, c)) {
              verdict[static_cast<std::size_t>(i)] = 2;
            } else if (simple(c)) {
              verdict[static_cast<std::size_t>(i)] = 1;
            }
          }
        });
    // The active points leave the list; simple ones are this pass's candidates.
    std::vector<std::int64_t> candidates;
    for (std::size_t i = 0; i < active.size(); ++i) {
      const std::int64_t p = active[i];
      flag(p) = static_cast<std::uint8_t>(flag(p) & ~kActive);
      if (verdict[i] == 2) {
        flag(p) |= kAnchor;
      } else if (verdict[i] == 1) {
        flag(p) |= kSimple;
        candidates.push_back(p);
      }
    }
    // 2. Around every candidate, in one gather: the object (at the start of the pass) and the
    // candidates, as 27-bit masks. Sorted candidates keep the gathers local.
    std::sort(candidates.begin(), candidates.end());
    const std::int64_t nc = static_cast<std::int64_t>(candidates.size());
    std::vector<std::uint32_t> around(candidates.size()), simple_around(candidates.size());
    parallel_chunks(nc, threads, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t i = b; i < e; ++i) {
        const std::int64_t p = candidates[static_cast<std::size_t>(i)];
        std::uint32_t n = 0, m = 0;
        for (int j = 0; j < 27; ++j) {
          const std::uint8_t g = flag(p + off27[static_cast<std::size_t>(j)]);
          n |= static_cast<std::uint32_t>(g & kObject) << j;
          m |= static_cast<std::uint32_t>((g & kSimple) != 0 ? 1u : 0u) << j;
        }
        around[static_cast<std::size_t>(i)] = n;
        simple_around[static_cast<std::size_t>(i)] = m;
      }
    });
    // 3. K_2, K_1, K_0: critical cliques made of candidates only and disjoint from the kernel
    // so far are kept whole, decided for each d on the kernel of the level above.
    const FaceTable& ft = FaceTable::get();
    for (int d = 2; d >= 0; --d) {
      const unsigned w = worker_count(threads, std::max<std::int64_t>(nc, 1));
      std::vector<std::vector<std::int64_t>> keep(w);
      parallel_for(w, w, [&](std::int64_t k) {
        auto& out = keep[static_cast<std::size_t>(k)];
        for (std::int64_t i = chunk_bound(nc, k, w); i < chunk_bound(nc, k + 1, w); ++i) {
          const std::int64_t p = candidates[static_cast<std::size_t>(i)];
          const std::uint32_t n = around[static_cast<std::size_t>(i)];
          for (int fi : ft.of_dim[static_cast<std::size_t>(d)]) {
            const std::uint32_t clique = n & ft.face[static_cast<std::size_t>(fi)].incident;
            // Each clique once, from its first point; only cliques of candidates matter (any
            // other meets the kernel already), and only critical ones not met at a level above.
            if (clique == 0 || (clique & ((1u << 13) - 1)) != 0) continue;
            if ((clique & ~simple_around[static_cast<std::size_t>(i)]) != 0) continue;
            if (!critical_face(n, fi)) continue; // arithmetic only: before the look-ups
            // No point of it kept at a level above (nothing is kept above the squares).
            bool free = true;
            for (std::uint32_t m = d == 2 ? 0u : clique; m != 0 && free; m &= m - 1) {
              const std::uint8_t g = flag(p + off27[static_cast<std::size_t>(std::countr_zero(m))]);
              free = (g & kKept) == 0;
            }
            if (!free) continue;
            for (std::uint32_t m = clique; m != 0; m &= m - 1) {
              out.push_back(p + off27[static_cast<std::size_t>(std::countr_zero(m))]);
            }
          }
        }
      });
      for (const auto& v : keep) {
        for (std::int64_t q : v) flag(q) |= kKept;
      }
    }
    // 4. Delete the candidates outside the kernel.
    std::vector<std::int64_t> deleted;
    for (std::int64_t p : candidates) {
      if ((flag(p) & kKept) == 0) {
        flag(p) = static_cast<std::uint8_t>(flag(p) & ~(kObject | kSimple));
        deleted.push_back(p);
      } else {
        flag(p) = static_cast<std::uint8_t>(flag(p) & ~(kSimple | kKept));
      }
    }
    if (deleted.empty()) break;
    ++result.passes;
    result.deleted += static_cast<std::int64_t>(deleted.size());
    remaining -= static_cast<std::int64_t>(deleted.size());
    std::sort(deleted.begin(), deleted.end());
    if (options.deletions != nullptr) {
      for (std::int64_t p : deleted) options.deletions->push_back(vol.image_index(p));
    }
    // 5. The next active points: the candidates kept (still simple unless their neighbourhood
    // changed, and their cliques may no longer be crucial) and the object neighbours of the
    // deleted points. Any other point keeps its neighbourhood, hence its verdict: not simple.
    std::vector<std::int64_t> next;
    auto activate = [&](std::int64_t q) {
      if ((flag(q) & (kObject | kActive | kAnchor)) == kObject) {
        flag(q) |= kActive;
        next.push_back(q);
      }
    };
    for (std::int64_t p : candidates) activate(p);
    for (std::int64_t p : deleted) {
      for (int j = 0; j < neighbours; ++j) activate(p + vol.offset[static_cast<std::size_t>(j)]);
    }
    active.swap(next);
    if (options.progress) options.progress({remaining, result.deleted, result.passes});
  }
  if (options.progress) options.progress({remaining, result.deleted, result.passes});
  result.skeleton = vol.object(image.domain());
  return result;
}

} // namespace zdg
