#include <zdg/kernel/transforms/out_of_core_transform.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/mapped_file.hpp>
#include <zdg/kernel/transforms/distance_transform.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include <algorithm>
#include <atomic>
#include <limits>
#include <memory>
#include <type_traits>

#include <sys/mman.h>
#include <unistd.h>

namespace zdg {

namespace {

std::uint64_t page_size() {
  static const std::uint64_t page = [] {
    const long p = ::sysconf(_SC_PAGESIZE);
    return p > 0 ? static_cast<std::uint64_t>(p) : std::uint64_t{4096};
  }();
  return page;
}

// Gives the whole pages inside [p, p + bytes) back to the kernel (file-backed mappings only:
// their content stays in the file and the page cache).
void release(const void* p, std::uint64_t bytes, bool mapped) {
  if (!mapped || bytes == 0) return;
  const std::uintptr_t pg = page_size(), a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (a + pg - 1) / pg * pg, hi = (a + bytes) / pg * pg;
  if (hi > lo) ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);
}

std::string bytes_text(std::uint64_t b) {
  return std::to_string(b) + " bytes";
}

} // namespace

template <class T>
std::uint64_t in_memory_transform_bytes(const Domain& dom, const TransformOptions& opt,
                                        int mask_item_bytes) {
  const auto n = static_cast<std::uint64_t>(dom.size());
  const auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  const std::uint64_t width = detail::engine_value_bytes(bounds.width);
  const std::uint64_t engine = width != 0 ? width : sizeof(BigInt);
  const std::uint64_t temp = engine == sizeof(T) ? 0 : n * engine;
  return n * static_cast<std::uint64_t>(mask_item_bytes) + n * sizeof(T) + temp;
}

template <class T>
T distance_transform_out_of_core(const Domain& dom, const std::uint8_t* mask, int item,
                                 const TransformOptions& opt, ReservedFile& out,
                                 std::uint64_t out_offset, const OutOfCoreOptions& ooc) {
  detail::require_mask_item_bytes(item, "out-of-core transform");
  if (dom.dim() < 2) {
    throw InvalidArgument("out-of-core transform: a 1-D image has one axis only (its slabs "
                          "would be the whole line): use the in-memory transform");
  }
  const auto bounds = detail::envelope_bounds(dom, opt, BigInt(0));
  detail::require_output_fits(bounds, opt, BigInt(std::numeric_limits<T>::max()),
                              "distance transform");
  if (bounds.width != detail::ValueWidth::I32 && bounds.width != detail::ValueWidth::I64) {
    throw InvalidArgument("out-of-core transform: the intermediate values of " + opt.metric.name() +
                          " on this domain need more than 64 bits (bound " + bounds.need.str() +
                          "); use the in-memory transform");
  }
  const bool mapped = ooc.mask_is_mapped_file;
  const auto uitem = static_cast<std::uint64_t>(item);
  const std::int64_t n0 = dom.extent(0), slice = dom.stride(0);
  const auto uslice = static_cast<std::uint64_t>(slice), un0 = static_cast<std::uint64_t>(n0);
  OutOfCoreProgress prog;
  auto report = [&](const char* phase, std::int64_t done, std::int64_t total) {
    if (!ooc.progress) return;
    prog.phase = phase;
    prog.done = done;
    prog.total = total;
    ooc.progress(prog);
  };

  // A background point, looked for chunk by chunk (the chunks released as they are read).
  {
    bool found = false;
    const std::uint64_t total = static_cast<std::uint64_t>(dom.size()) * uitem;
    const std::uint64_t chunk =
        std::max<std::uint64_t>(page_size(), ooc.memory_budget / 4 / uitem * uitem);
    for (std::uint64_t at = 0; at < total && !found; at += chunk) {
      const std::uint64_t len = std::min(chunk, total - at);
      for (std::uint64_t i = at; i < at + len && !found; i += uitem) {
        bool zero = true;
        for (std::uint64_t b = 0; b < uitem; ++b) zero = zero && mask[i + b] == 0;
        found = zero;
      }
      release(mask + at, len, mapped);
    }
    if (!found) require_background(dom, mask, opt, item); // throws its message
  }

  T largest = 0;
  detail::with_value_type(bounds.width, [&]<class V>(std::type_identity<V>) {
    if constexpr (std::is_same_v<V, std::int32_t> || std::is_same_v<V, std::int64_t>) {
      const V inf = detail::envelope_infinity<V>(bounds);
      const std::uint64_t per_slice = uslice * (uitem + sizeof(V));
      if (ooc.memory_budget < per_slice) {
        throw InvalidArgument("out-of-core transform: a memory budget of " +
                              bytes_text(ooc.memory_budget) +
                              " is below one slice of the mask "
                              "and the values (" +
                              bytes_text(per_slice) + ")");
      }
      // Where the values live between the phases: the output itself when it has the engine's
      // width, else a scratch file (unlinked at once: it disappears with the run).
      std::unique_ptr<ReservedFile> scratch;
      ReservedFile* values = &out;
      std::uint64_t values_offset = out_offset;
      if constexpr (sizeof(V) != sizeof(T)) {
        if (ooc.scratch_folder.empty()) {
          throw InvalidArgument("out-of-core transform: the output type is narrower than the "
                                "engine's values and no scratch folder was given");
        }
        static std::atomic<unsigned> serial{0};
        const std::string path = ooc.scratch_folder + "/.zdg-ooc-scratch-" +
                                 std::to_string(::getpid()) + "-" + std::to_string(serial++);
        scratch = std::make_unique<ReservedFile>(path, static_cast<std::uint64_t>(dom.size()) *
                                                           sizeof(V));
        ::unlink(path.c_str());
        values = scratch.get();
        values_offset = 0;
      }

      // (1) Slabs of whole slices: the mask pass and the passes along axes d-1 .. 1.
      const std::int64_t s = std::max<std::int64_t>(
          1, std::min<std::int64_t>(n0, static_cast<std::int64_t>(ooc.memory_budget / per_slice)));
      std::vector<V> slab_values(static_cast<std::size_t>(s) * uslice);
      detail::EnvelopePart slices;
      slices.axis0 = false;
      for (std::int64_t z0 = 0; z0 < n0; z0 += s) {
        const std::int64_t z1 = std::min(n0, z0 + s);
        std::vector<std::int64_t> ext = dom.extents();
        ext[0] = z1 - z0;
        const Domain slab(ext);
        const std::uint8_t* m = mask + static_cast<std::uint64_t>(z0) * uslice * uitem;
        detail::separable_envelope_part<V>(slab, opt, m, slab_values.data(), inf, nullptr, item,
                                           slices);
        const auto cells = static_cast<std::uint64_t>(z1 - z0) * uslice;
        values->write(values_offset + static_cast<std::uint64_t>(z0) * uslice * sizeof(V),
                      slab_values.data(), cells * sizeof(V));
        release(m, cells * uitem, mapped);
        prog.bytes_read += cells * uitem;
        prog.bytes_written += cells * sizeof(V);
        report("slices", z1, n0);
      }
      // Freed before the blocks are allocated (`slab_values = {}` would assign an empty list
      // and keep the capacity: the slab and the block together were 1.3 x the budget).
      std::vector<V>().swap(slab_values);

      // (2) Blocks of b columns: the block's part of every slice, read into an n0 x b array
      // whose axis 0 is the volume's, transformed along it, written to the output.
      const std::uint64_t per_column =
          un0 * (sizeof(V) + (sizeof(V) == sizeof(T) ? 0 : sizeof(T))); // block (+ converted)
      const auto b = static_cast<std::int64_t>(
          std::clamp<std::uint64_t>(ooc.memory_budget / per_column, 1, uslice));
      std::vector<V> block(static_cast<std::size_t>(n0 * b));
      std::vector<T> converted(sizeof(V) == sizeof(T) ? 0 : static_cast<std::size_t>(n0 * b));
      TransformOptions column_opt = opt;
      column_opt.torus = {opt.periodic(0), false};
      detail::EnvelopePart columns;
      columns.slices = false;
      columns.from_mask = true;
      for (std::int64_t c0 = 0; c0 < slice; c0 += b) {
        const std::int64_t w = std::min(b, slice - c0);
        const auto uw = static_cast<std::uint64_t>(w);
        for (std::int64_t z = 0; z < n0; ++z) {
          values->read(values_offset + (static_cast<std::uint64_t>(z) * uslice +
                                        static_cast<std::uint64_t>(c0)) *
                                           sizeof(V),
                       block.data() + z * w, uw * sizeof(V));
        }
        const Domain cols({n0, w});
        detail::separable_envelope_part<V>(cols, column_opt, nullptr, block.data(), inf, nullptr,
                                           item, columns);
        const void* rows = block.data();
        if constexpr (sizeof(V) != sizeof(T)) {
          for (std::int64_t i = 0; i < n0 * w; ++i)
            converted[static_cast<std::size_t>(i)] =
                static_cast<T>(block[static_cast<std::size_t>(i)]);
          rows = converted.data();
        }
        const T* t = static_cast<const T*>(rows);
        for (std::int64_t i = 0; i < n0 * w; ++i) largest = std::max(largest, static_cast<T>(t[i]));
        for (std::int64_t z = 0; z < n0; ++z) {
          out.write(out_offset +
                        (static_cast<std::uint64_t>(z) * uslice + static_cast<std::uint64_t>(c0)) *
                            sizeof(T),
                    t + z * w, uw * sizeof(T));
        }
        prog.bytes_read += uw * un0 * sizeof(V);
        prog.bytes_written += uw * un0 * sizeof(T);
        report("axis 0", c0 + w, slice);
      }
    } else {
      throw InvalidArgument("out-of-core transform: 64-bit engines only"); // excluded above
    }
  });
  return largest;
}

#define ZDG_OOC_INSTANTIATE(T)                                                                     \
  template T distance_transform_out_of_core(const Domain&, const std::uint8_t*, int,               \
                                            const TransformOptions&, ReservedFile&, std::uint64_t, \
                                            const OutOfCoreOptions&);                              \
  template std::uint64_t in_memory_transform_bytes<T>(const Domain&, const TransformOptions&, int);
ZDG_OOC_INSTANTIATE(std::uint8_t)
ZDG_OOC_INSTANTIATE(std::uint16_t)
ZDG_OOC_INSTANTIATE(std::uint32_t)
ZDG_OOC_INSTANTIATE(std::uint64_t)
#undef ZDG_OOC_INSTANTIATE

} // namespace zdg
