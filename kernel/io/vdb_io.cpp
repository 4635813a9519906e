#include <zdg/kernel/io/vdb_io.hpp>

#include <zdg/arith/error.hpp>

#ifdef ZDG_HAVE_OPENVDB
#include <zdg/kernel/io/vdb_module.hpp>

#include <dlfcn.h>
#endif

#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace zdg {

#ifndef ZDG_HAVE_OPENVDB

bool vdb_supported() {
  return false;
}

ScalarVolume read_vdb(const std::string& path) {
  throw IoError(path + ": this zdg was built without OpenVDB (install libopenvdb-dev and rebuild)");
}

void write_vdb(const std::string& path, const ScalarVolume& /*volume*/) {
  throw IoError(path + ": this zdg was built without OpenVDB (install libopenvdb-dev and rebuild)");
}

#else

namespace {

// The module, loaded once (the paths tried: below); IoError naming the first failure.
const VdbModule& vdb_module(const std::string& path) {
  static const VdbModule* module = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    static const VdbHost host{
        &dtype_name,
        &dtype_is_float,
        &dtype_from_name,
        [](DType t, std::vector<std::int64_t> shape, const std::vector<std::int64_t>& v) {
          return make_npy(t, std::move(shape), v);
        },
        [](const NpyArray& a) { return a.count(); },
        [](const ScalarVolume& v, std::int64_t i) { return v.value(i); },
        [](const ScalarVolume& v) { v.validate(); }};
    // Where this build put it, where it is installed, then beside the program or library
    // holding this code and in its ../lib/zdg (a relocated installation).
    std::vector<std::string> files{ZDG_VDB_MODULE_BUILD, ZDG_VDB_MODULE_INSTALL};
    Dl_info self{};
    if (::dladdr(reinterpret_cast<void*>(&vdb_supported), &self) != 0 &&
        self.dli_fname != nullptr && std::string(self.dli_fname).find('/') != std::string::npos) {
      const std::string here(self.dli_fname);
      const std::string dir = here.substr(0, here.find_last_of('/') + 1);
      const std::string name =
          std::string(ZDG_VDB_MODULE_INSTALL)
              .substr(std::string(ZDG_VDB_MODULE_INSTALL).find_last_of('/') + 1);
      files.push_back(dir + name);
      files.push_back(dir + "../lib/zdg/" + name);
    }
    for (const std::string& path_of : files) {
      const char* file = path_of.c_str();
      void* h = ::dlopen(file, RTLD_NOW | RTLD_LOCAL);
      if (h == nullptr) {
        const char* why = ::dlerror();
        if (failure.empty()) failure = why != nullptr ? why : file;
        continue;
      }
      auto entry = reinterpret_cast<ZdgVdbModuleEntry>(::dlsym(h, "zdg_vdb_module"));
      const VdbModule* m = entry != nullptr ? entry(&host) : nullptr;
      if (m != nullptr && m->version == kVdbModuleVersion) {
        module = m;
        return;
      }
      failure = std::string(file) + " is not this build's OpenVDB module";
      ::dlclose(h);
    }
  });
  if (module == nullptr)
    throw IoError(path + ": cannot load zdg's OpenVDB module (" + failure + ")");
  return *module;
}

} // namespace

bool vdb_supported() {
  return true;
}

ScalarVolume read_vdb(const std::string& path) {
  return vdb_module(path).read(path);
}

void write_vdb(const std::string& path, const ScalarVolume& v) {
  vdb_module(path).write(path, v);
}

#endif

} // namespace zdg
