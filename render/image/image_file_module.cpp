#include "render/image/image_file_module.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "core/support/error.h"

namespace gps {
namespace {

namespace fs = std::filesystem;

// The folders to look in: that of the caller's own file (a wheel keeps the module beside the Python
// module) with the install's library folder as seen from the programs' folders (bin/,
// libexec/gpsurf/); this build's; then the same from the running program's folder (the loader knows a
// main program by the name it was started as, which gpsurf-render, started as gpsurf, is not).
std::vector<fs::path> module_folders() {
  std::vector<fs::path> folders;
  const auto add = [&](const fs::path& folder) {
    if (std::find(folders.begin(), folders.end(), folder.lexically_normal()) == folders.end())
      folders.push_back(folder.lexically_normal());
  };
  const auto add_from = [&](const fs::path& base) {
    for (const fs::path& folder :
         {base, base / GPSURF_IMAGE_MODULE_FROM_BINDIR, base / GPSURF_IMAGE_MODULE_FROM_LIBEXECDIR})
      add(folder);
  };
  std::error_code ec;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&module_folders), &info) && info.dli_fname)
    add_from(fs::weakly_canonical(fs::path(info.dli_fname), ec).parent_path());
  add(GPSURF_IMAGE_MODULE_BUILD_DIR);
  if (const fs::path program = fs::read_symlink("/proc/self/exe", ec); !ec) add_from(program.parent_path());
  return folders;
}

const ImageFileFunctions* load(std::string& failure) {
  std::string tried;
  for (const fs::path& folder : module_folders()) {
    const fs::path file = folder / GPSURF_IMAGE_MODULE_FILE;
    std::error_code ec;
    if (!fs::exists(file, ec)) {
      tried += (tried.empty() ? "" : ", ") + folder.string();
      continue;
    }
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      failure = file.string() + " cannot be loaded (" + std::string(why ? why : "unknown").substr(0, 160) + ")";
      return nullptr;
    }
    using Entry = const ImageFileFunctions* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageFileEntry));
    const ImageFileFunctions* functions = entry ? entry() : nullptr;
    if (functions && functions->layout == kImageFileLayout && functions->size == sizeof(ImageFileFunctions))
      return functions;
    dlclose(handle);
    tried += (tried.empty() ? "" : ", ") + folder.string() + " (another build's)";
  }
  failure =
      "OpenImageIO's formats need " + std::string(GPSURF_IMAGE_MODULE_FILE) + " of this build, not found in " + tried;
  return nullptr;
}

}  // namespace

const ImageFileFunctions& openimageio_files(const std::string& what) {
  static std::once_flag once;
  static const ImageFileFunctions* functions = nullptr;
  static std::string failure;
  std::call_once(once, [] { functions = load(failure); });
  if (!functions) throw Error(what + ": " + failure);
  return *functions;
}

}  // namespace gps
