#include <zdg/kernel/transforms/linf_covering.hpp>

#include <zdg/kernel/transforms/separable_engine.hpp>

#include <deque>

namespace zdg::detail {

namespace {

// One line: in[e], e in [0, len); out[x - qlo] for x in [qlo, qhi): max in[c] with
// |x - c| < in[c]; arg: a maximiser position (deterministic on ties), -1 if none.
void cover_line(const std::int64_t* in, std::int64_t len, std::int64_t qlo, std::int64_t qhi,
                std::int64_t* out, std::int64_t* arg, std::vector<std::int64_t>& dq) {
  for (std::int64_t x = qlo; x < qhi; ++x) {
    out[x - qlo] = 0;
    arg[x - qlo] = -1;
  }
  // Left candidates (c <= x), then right ones (c >= x); deque kept in decreasing value.
  for (int dir = 0; dir < 2; ++dir) {
    dq.clear();
    std::size_t head = 0;
    auto pos = [&](std::int64_t k) { return dir == 0 ? k : len - 1 - k; };
    for (std::int64_t k = 0; k < len; ++k) {
      const std::int64_t c = pos(k);
      if (in[c] > 0) {
        // drop candidates with a value <= in[c]: c reaches at least as far in this direction
        while (dq.size() > head && in[dq.back()] <= in[c]) dq.pop_back();
        dq.push_back(c);
      }
      const std::int64_t x = c;
      while (dq.size() > head) {
        const std::int64_t f = dq[head];
        const std::int64_t dist = x > f ? x - f : f - x;
        if (dist < in[f]) break;
        ++head;
      }
      if (x < qlo || x >= qhi || dq.size() == head) continue;
      const std::int64_t best = dq[head];
      std::int64_t& o = out[x - qlo];
      std::int64_t& a = arg[x - qlo];
      if (in[best] > o || (in[best] == o && best < a)) {
        o = in[best];
        a = best;
      }
    }
  }
}

} // namespace

void linf_covering(const Domain& dom, const TransformOptions& opt, std::vector<std::int64_t>& r,
                   std::vector<std::int64_t>* sites) {
  const unsigned threads = resolve_threads(opt.threads, dom.size());
  if (sites != nullptr) {
    sites->resize(r.size());
    for (std::size_t i = 0; i < r.size(); ++i)
      (*sites)[i] = r[i] > 0 ? static_cast<std::int64_t>(i) : -1;
  }
  for (int a = dom.dim() - 1; a >= 0; --a) {
    const std::int64_t n = dom.extent(a), st = dom.stride(a);
    const bool periodic = opt.periodic(a);
    const std::int64_t len = periodic ? 3 * n : n, qlo = periodic ? n : 0;
    const std::int64_t lines = dom.size() / n;
    parallel_chunks(lines, threads, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::int64_t> in(static_cast<std::size_t>(len)), out(static_cast<std::size_t>(n)),
          arg(static_cast<std::size_t>(n)), oldsite(static_cast<std::size_t>(n)), dq;
      for (std::int64_t line = begin; line < end; ++line) {
        const std::int64_t base = (line / st) * n * st + line % st;
        for (std::int64_t x = 0; x < n; ++x) {
          const std::int64_t v = r[static_cast<std::size_t>(base + x * st)];
          for (std::int64_t c = 0; c < len / n; ++c) in[static_cast<std::size_t>(c * n + x)] = v;
          if (sites != nullptr)
            oldsite[static_cast<std::size_t>(x)] =
                (*sites)[static_cast<std::size_t>(base + x * st)];
        }
        cover_line(in.data(), len, qlo, qlo + n, out.data(), arg.data(), dq);
        for (std::int64_t x = 0; x < n; ++x) {
          r[static_cast<std::size_t>(base + x * st)] = out[static_cast<std::size_t>(x)];
          if (sites != nullptr) {
            const std::int64_t e = arg[static_cast<std::size_t>(x)];
            (*sites)[static_cast<std::size_t>(base + x * st)] =
                e < 0 ? -1 : oldsite[static_cast<std::size_t>(e % n)];
          }
        }
      }
    });
  }
}

} // namespace zdg::detail
