#include "core/base/oiio_module.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "core/base/errors.h"

// Where the installed tree keeps the module, relative to the installed
// executable's folder (set by src/core/base/CMakeLists.txt from GNUInstallDirs).
#ifndef SHADELAB_OIIO_MODULE_FROM_BINDIR
#define SHADELAB_OIIO_MODULE_FROM_BINDIR "../lib/shadelab"
#endif

namespace shadelab::oiio {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFileName = "libshadelab_oiio.so";

std::mutex loadMutex;
Module* loaded = nullptr;

std::vector<std::string> candidates() {
  std::vector<std::string> paths;
  if (const char* named = std::getenv("SHADELAB_OIIO_MODULE"); named && *named) {
    paths.push_back(named);  // explicit: nothing else is tried
    return paths;
  }
  std::error_code error;
  fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    fs::path folder = executable.parent_path();
    paths.push_back((folder / kFileName).string());
    paths.push_back((folder / SHADELAB_OIIO_MODULE_FROM_BINDIR / kFileName).lexically_normal());
  }
  paths.push_back(kFileName);  // dlopen's search: RUNPATH, LD_LIBRARY_PATH, ld.so.cache
  return paths;
}

}  // namespace

Module& oiioModule(const std::string& purpose) {
  std::lock_guard lock(loadMutex);
  if (loaded) return *loaded;
  std::string reasons;
  for (const std::string& path : candidates()) {
    bool searched = path.find('/') == std::string::npos;
    std::error_code error;
    if (!searched && !fs::exists(path, error)) {
      reasons += "\n  " + path + ": no such file";
      continue;
    }
    // RTLD_LOCAL: OpenImageIO's symbols stay out of the global namespace.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      reasons += "\n  " + path + ": " + (why ? why : "dlopen failed");
      continue;
    }
    auto entry = reinterpret_cast<EntryPoint>(dlsym(handle, kEntryPoint));
    Module* module = entry ? entry() : nullptr;
    if (!module || module->interfaceVersion() != kInterfaceVersion) {
      reasons += "\n  " + path + ": not a shadelab OpenImageIO module of interface version " +
                 std::to_string(kInterfaceVersion);
      dlclose(handle);
      continue;
    }
    // Never closed: OpenImageIO's plugins and caches live until exit.
    loaded = module;
    return *loaded;
  }
  throw InputError("cannot " + purpose +
                   ": it needs shadelab's OpenImageIO module (libshadelab_oiio.so), which could "
                   "not be loaded (set SHADELAB_OIIO_MODULE to its path):" +
                   reasons);
}

bool oiioModuleLoaded() {
  std::lock_guard lock(loadMutex);
  return loaded != nullptr;
}

}  // namespace shadelab::oiio
