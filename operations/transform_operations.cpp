#include <zdg/operations/transform_operations.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/mapped_file.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/kernel/parallel/populate_pages.hpp>
#include <zdg/kernel/transforms/separable_engine.hpp>

#include <chrono>
#include <filesystem>
#include <limits>
#include <memory>
#include <type_traits>

namespace zdg {

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class T>
NpyTransformResult lean_dt_as(const NpyTransformOptions& o, const NpyLayout& lay, const Domain& dom,
                              DType dtype) {
  const auto t0 = std::chrono::steady_clock::now();
  const TransformOptions& opt = o.transform;
  MappedInput in(o.input);
  const std::uint8_t* mask = in.data() + lay.data_offset;
  const int item = static_cast<int>(dtype_size(lay.dtype));
  NpyTransformResult r;
  r.domain = dom;
  r.dtype = dtype;
  r.in_memory_bytes = in_memory_transform_bytes<T>(dom, opt, item);
  r.memory_budget = o.memory_budget ? *o.memory_budget : std::uint64_t{4} << 30;
  r.out_of_core = o.out_of_core || (o.memory_budget && r.in_memory_bytes > r.memory_budget);
  // In memory, the background is checked before the output's space is reserved (out of core,
  // the transform checks it slab by slab, within the budget).
  if (!r.out_of_core) require_background(dom, mask, opt, item);
  const std::string header = npy_header_bytes(dtype, lay.shape);
  const auto n = static_cast<std::uint64_t>(dom.size());
  ReservedFile out(o.output, header.size() + n * sizeof(T)); // a disk too small fails here
  out.write(0, header.data(), header.size());
  if (r.out_of_core) {
    OutOfCoreOptions ooc;
    ooc.memory_budget = r.memory_budget;
    const std::filesystem::path folder = std::filesystem::path(o.output).parent_path();
    ooc.scratch_folder = (folder.empty() ? std::filesystem::path(".") : folder).string();
    ooc.mask_is_mapped_file = true;
    ooc.progress = o.out_of_core_progress;
    r.max_value = distance_transform_out_of_core<T>(dom, mask, item, opt, out, header.size(), ooc);
    r.seconds = since(t0);
    out.finish();
    return r;
  }
  const unsigned workers = worker_count(opt.threads, dom.size());
  if (o.shared_output ? *o.shared_output : shared_mapping_fits(out.size())) {
    // In memory, in the output file's pages (mapped by the workers): no buffer, no copy. The
    // header (written above) is padded to 64 bytes (npy_header_bytes): the values are aligned.
    {
      const SharedMapping map(out, workers);
      T* values = reinterpret_cast<T*>(map.data() + header.size());
      std::uint64_t mx = 0; // (taken by the last pass while its lines are in cache)
      distance_transform_into<T>(dom, mask, item, opt, values, o.pass_progress, &mx);
      r.seconds = since(t0);
      r.max_value = mx;
    }
    out.finish();
    return r;
  }
  // In memory: the values in a buffer of the output's type (not zero-filled: the transform
  // writes every value), then one sequential write.
  std::unique_ptr<T[]> values(new T[n]);
  // mapped (in huge pages where offered) by all the workers before the passes write it
  populate_pages(values.get(), n * sizeof(T), workers);
  distance_transform_into<T>(dom, mask, item, opt, values.get(), o.pass_progress);
  r.seconds = since(t0);
  // The largest value and the write, in pieces by all the workers (write_values_max).
  r.max_value = write_values_max<T>(out, header.size(), values.get(), dom.size(), workers);
  values.reset();
  out.finish();
  return r;
}

} // namespace

std::optional<DType> narrowest_unsigned(const BigInt& bound) {
  if (bound <= 255) return DType::U8;
  if (bound <= 65535) return DType::U16;
  if (bound <= BigInt(4294967295ULL)) return DType::U32;
  if (bound <= BigInt(std::numeric_limits<std::uint64_t>::max())) return DType::U64;
  return std::nullopt;
}

std::optional<NpyTransformResult> npy_distance_transform(const NpyTransformOptions& o) {
  const NpyLayout lay = read_npy_layout(o.input);
  if (lay.fortran_order) {
    // The mapped passes read the file in C order: a Fortran-order file is read and reordered.
    if (o.out_of_core)
      throw InvalidArgument("--out-of-core: " + o.input +
                            " is a Fortran-order array; the out-of-core transform maps C-order "
                            "arrays (save it with np.ascontiguousarray)");
    return std::nullopt;
  }
  if (dtype_is_float(lay.dtype)) {
    // -0.0 is background: not a bytewise test, so floats take the general path.
    if (o.out_of_core)
      throw InvalidArgument("--out-of-core: " + o.input + " holds " + dtype_name(lay.dtype) +
                            " values; the out-of-core transform reads integer or bool masks");
    return std::nullopt;
  }
  if (lay.shape.empty()) throw IoError(o.input + ": a 0-dimensional array is not an image");
  for (auto e : lay.shape)
    if (e == 0) throw IoError(o.input + ": empty array (an extent is 0)");
  if (!o.lower.empty() && o.lower.size() != lay.shape.size())
    throw InvalidArgument("--lower: " + std::to_string(o.lower.size()) + " bounds for a " +
                          std::to_string(lay.shape.size()) + "-dimensional image");
  const Domain dom(lay.shape, o.lower);
  const BigInt bound = distance_transform_max_value(dom, o.transform);
  const auto dtype = narrowest_unsigned(bound);
  if (!dtype) {
    if (o.out_of_core)
      throw InvalidArgument("--out-of-core: values up to " + bound.str() +
                            " do not fit 64 bits; use the in-memory transform");
    return std::nullopt;
  }
  std::optional<NpyTransformResult> r;
  with_unsigned(*dtype,
                [&]<class T>(std::type_identity<T>) { r = lean_dt_as<T>(o, lay, dom, *dtype); });
  return r;
}

} // namespace zdg
