#include <zdg/kernel/transforms/distance_transform.hpp>

#include <zdg/kernel/parallel/populate_pages.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include <algorithm>
#include <limits>
#include <mutex>
#include <string>

namespace zdg {

namespace {

template <class T, class V>
T convert_value(const V& v) {
  if constexpr (std::is_same_v<T, BigInt>) {
    return detail::engine_to_bigint(v);
  } else if constexpr (std::is_same_v<V, BigInt>) {
    return v.template convert_to<T>();
  } else {
    return static_cast<T>(v);
  }
}

} // namespace

BigInt distance_transform_max_value(const Domain& domain, const TransformOptions& opt) {
  return detail::envelope_bounds(domain, opt, BigInt(0)).value_max;
}

void require_background(const Image<std::uint8_t>& shape, const TransformOptions& opt) {
  require_background(shape.domain(), shape.values().data(), opt);
}

void require_background(const Domain& dom, const std::uint8_t* mask, const TransformOptions& opt,
                        int mask_item_bytes) {
  const auto item = static_cast<std::int64_t>(mask_item_bytes);
  bool found = false;
  for (std::int64_t i = 0; i < dom.size() && !found; ++i) {
    const std::uint8_t* p = mask + i * item;
    found = std::all_of(p, p + item, [](std::uint8_t b) { return b == 0; });
  }
  if (!found) detail::throw_no_background(opt);
}

namespace detail {
void throw_no_background(const TransformOptions& opt) {
  bool torus = std::any_of(opt.torus.begin(), opt.torus.end(), [](bool b) { return b; });
  throw InvalidArgument(std::string("distance transform: the image has no background point "
                                    "(value 0)") +
                        (torus ? ", also on the torus" : "") +
                        ": every distance would be infinite");
}
} // namespace detail

template <class T>
void distance_transform_into(const Domain& dom, const std::uint8_t* mask, int mask_item_bytes,
                             const TransformOptions& opt, T* out,
                             const std::function<void(int, int)>& progress,
                             std::uint64_t* max_value) {
  detail::require_mask_item_bytes(mask_item_bytes, "distance transform");
  auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  require_background(dom, mask, opt, mask_item_bytes);
  if constexpr (!std::is_same_v<T, BigInt>) {
    detail::require_output_fits(bounds, opt, BigInt(std::numeric_limits<T>::max()),
                                "distance transform");
  }
  detail::EnvelopePart whole;
  if (progress) {
    whole.after_pass = [&, done = 0](int) mutable { progress(++done, dom.dim()); };
  }
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    V inf = detail::envelope_infinity<V>(bounds);
    if constexpr (std::is_integral_v<V> && std::is_integral_v<T> && sizeof(V) == sizeof(T)) {
      // Same width: work in the output buffer (signed and unsigned variants may alias; the
      // final values are >= 0 and finite since there is background). The largest value from
      // the last pass (axis 0) while its lines are in cache; in 1D, by a scan.
      std::uint64_t mx = 0;
      if (max_value != nullptr && dom.dim() >= 2) whole.max_value = &mx;
      detail::separable_envelope_part<V>(dom, opt, mask, reinterpret_cast<V*>(out), inf, nullptr,
                                         mask_item_bytes, whole);
      if (max_value != nullptr) {
        if (dom.dim() < 2) {
          for (std::int64_t i = 0; i < dom.size(); ++i)
            mx = std::max(mx, static_cast<std::uint64_t>(out[i]));
        }
        *max_value = mx;
      }
      return;
    }
    std::vector<V> f;
    assign_populated(f, static_cast<std::size_t>(dom.size()),
                     detail::resolve_threads(opt.threads, dom.size()));
    detail::separable_envelope_part<V>(dom, opt, mask, f.data(), inf, nullptr, mask_item_bytes,
                                       whole);
    const V* fp = f.data();
    std::mutex lock;
    std::uint64_t mx = 0;
    parallel_chunks(dom.size(), detail::resolve_threads(opt.threads, dom.size()),
                    [&](std::int64_t b, std::int64_t e) {
                      std::uint64_t m = 0;
                      for (std::int64_t i = b; i < e; ++i) {
                        out[i] = convert_value<T>(fp[i]);
                        if constexpr (!std::is_same_v<T, BigInt>) {
                          m = std::max(m, static_cast<std::uint64_t>(out[i]));
                        }
                      }
                      const std::lock_guard<std::mutex> hold(lock);
                      mx = std::max(mx, m);
                    });
    if (max_value != nullptr) *max_value = mx;
  });
}

template <class T>
Image<T> distance_transform(const Image<std::uint8_t>& shape, const TransformOptions& opt) {
  // The output's pages are mapped by all the workers (the fill itself is then a memset at
  // memory speed instead of one page fault per 4 KiB on one thread).
  std::vector<T> values;
  assign_populated(values, static_cast<std::size_t>(shape.size()),
                   detail::resolve_threads(opt.threads, shape.size()));
  Image<T> out(shape.domain(), std::move(values));
  distance_transform_into<T>(shape.domain(), shape.values().data(), 1, opt, out.values().data());
  return out;
}

template void distance_transform_into(const Domain&, const std::uint8_t*, int,
                                      const TransformOptions&, std::uint8_t*,
                                      const std::function<void(int, int)>&, std::uint64_t*);
template void distance_transform_into(const Domain&, const std::uint8_t*, int,
                                      const TransformOptions&, std::uint16_t*,
                                      const std::function<void(int, int)>&, std::uint64_t*);
template void distance_transform_into(const Domain&, const std::uint8_t*, int,
                                      const TransformOptions&, std::uint32_t*,
                                      const std::function<void(int, int)>&, std::uint64_t*);
template void distance_transform_into(const Domain&, const std::uint8_t*, int,
                                      const TransformOptions&, std::uint64_t*,
                                      const std::function<void(int, int)>&, std::uint64_t*);
template void distance_transform_into(const Domain&, const std::uint8_t*, int,
                                      const TransformOptions&, std::int64_t*,
                                      const std::function<void(int, int)>&, std::uint64_t*);
template Image<std::uint8_t> distance_transform(const Image<std::uint8_t>&,
                                                const TransformOptions&);
template Image<std::uint16_t> distance_transform(const Image<std::uint8_t>&,
                                                 const TransformOptions&);
template Image<std::uint32_t> distance_transform(const Image<std::uint8_t>&,
                                                 const TransformOptions&);
template Image<std::uint64_t> distance_transform(const Image<std::uint8_t>&,
                                                 const TransformOptions&);
template Image<std::int64_t> distance_transform(const Image<std::uint8_t>&,
                                                const TransformOptions&);
template Image<BigInt> distance_transform(const Image<std::uint8_t>&, const TransformOptions&);

} // namespace zdg
