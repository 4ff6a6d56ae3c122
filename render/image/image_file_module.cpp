#include "render/image/image_file_module.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "core/support/error.h"

namespace gps {
namespace {

namespace fs = std::filesystem;

// The folders to look in: those of the caller's own file (a wheel keeps the module beside the Python
// module) and of the running program (its loader knows the main program by the name it was started
// as), each with the install's library folder as seen from the programs' folders; then this build's.
std::vector<fs::path> module_folders() {
  std::vector<fs::path> bases, folders;
  std::error_code ec;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&module_folders), &info) && info.dli_fname)
    bases.push_back(fs::weakly_canonical(fs::path(info.dli_fname), ec).parent_path());
  if (const fs::path program = fs::read_symlink("/proc/self/exe", ec); !ec) bases.push_back(program.parent_path());
  for (const fs::path& base : bases)
    for (const fs::path& folder :
         {base, base / GPSURF_IMAGE_MODULE_FROM_BINDIR, base / GPSURF_IMAGE_MODULE_FROM_LIBEXECDIR})
      if (std::find(folders.begin(), folders.end(), folder.lexically_normal()) == folders.end())
        folders.push_back(folder.lexically_normal());
  folders.emplace_back(GPSURF_IMAGE_MODULE_BUILD_DIR);
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
    if (!entry) {
      failure = file.string() + " is not gpsurf's image module";
      return nullptr;
    }
    return entry();
  }
  failure = std::string(GPSURF_IMAGE_MODULE_FILE) + " (OpenImageIO's formats) is not installed: looked in " + tried;
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
