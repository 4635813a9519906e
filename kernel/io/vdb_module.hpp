// The interface between zdg and its OpenVDB module (kernel/io/vdb_module.cpp, libzdg_vdb.so),
// which kernel/io/vdb_io.cpp loads (dlopen) at the first .vdb file read or written instead of
// linking OpenVDB into every program (its relocations cost each process about 45 ms at start).
// Internal: the module's entry point zdg_vdb_module(host) takes the host's functions that the
// OpenVDB code calls and returns the module's. Both sides are compiled from the same headers;
// the version guards against a module left from another build.
#pragma once

#include <zdg/kernel/images/scalar_volume.hpp>
#include <zdg/kernel/io/npy_io.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace zdg {

inline constexpr int kVdbModuleVersion = 1;

struct VdbHost {
  std::string (*dtype_name)(DType);
  bool (*dtype_is_float)(DType);
  DType (*dtype_from_name)(const std::string&);
  NpyArray (*make_npy)(DType, std::vector<std::int64_t>, const std::vector<std::int64_t>&);
  std::int64_t (*npy_count)(const NpyArray&);
  double (*volume_value)(const ScalarVolume&, std::int64_t);
  void (*volume_validate)(const ScalarVolume&);
};

struct VdbModule {
  int version;
  ScalarVolume (*read)(const std::string& path);
  void (*write)(const std::string& path, const ScalarVolume& volume);
};

} // namespace zdg

extern "C" {
/// The module's entry point (the symbol vdb_io.cpp looks up).
using ZdgVdbModuleEntry = const zdg::VdbModule* (*)(const zdg::VdbHost*);
}
