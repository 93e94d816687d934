// SPDX-License-Identifier: MIT
// dlopen of the OpenImageIO module: only processes that read or write a non-PNG image pay for
// OpenImageIO's dependency tree (0.3 s and 130 MB at start-up when it was linked in).
#include "core/image/oiio_loader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace rt {

namespace {

namespace fs = std::filesystem;

/// The outcome of the one load attempt: the module's functions, or why there are none.
struct LoadResult {
    const ScadrayOiioApi *api = nullptr;
    std::string failure;
};

LoadResult load() {
    LoadResult result;
    std::string tried;
    for (const std::string &path : oiioModuleCandidates()) {
        std::string reason;
        if (void *handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
            auto entry = reinterpret_cast<ScadrayOiioEntry>(::dlsym(handle, SCADRAY_OIIO_ENTRY));
            const ScadrayOiioApi *api = entry ? entry() : nullptr;
            if (api && api->abiVersion == SCADRAY_OIIO_ABI_VERSION) {
                result.api = api;  // never unloaded: OpenImageIO keeps global state
                return result;
            }
            reason = api ? "built for another scadray version (interface " +
                               std::to_string(api->abiVersion) + ", this scadray needs " +
                               std::to_string(SCADRAY_OIIO_ABI_VERSION) + ")"
                         : std::string("not a scadray OpenImageIO module (no ") +
                               SCADRAY_OIIO_ENTRY + ")";
            ::dlclose(handle);
        } else {
            const char *err = ::dlerror();
            reason = err ? err : "cannot be loaded";
            if (reason.rfind(path + ": ", 0) == 0) reason.erase(0, path.size() + 2);
        }
        tried += (tried.empty() ? "" : "; ") + path + " (" + reason + ")";
    }
    result.failure = std::string("the OpenImageIO module ") + kOiioModuleName +
                     ", which reads and writes every image format but PNG, cannot be loaded; "
                     "tried " +
                     tried + ". Build the target scadray_oiio or set " + kOiioModuleEnv +
                     " to the module's path";
    return result;
}

}  // namespace

std::vector<std::string> oiioModuleCandidates() {
    if (const char *env = std::getenv(kOiioModuleEnv); env && *env) return {env};
    std::vector<std::string> paths;
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) paths.push_back((exe.parent_path() / kOiioModuleName).string());
#ifdef SCADRAY_OIIO_MODULE_PATH
    if (paths.empty() || paths.front() != SCADRAY_OIIO_MODULE_PATH)
        paths.push_back(SCADRAY_OIIO_MODULE_PATH);
#endif
    return paths;
}

const ScadrayOiioApi &oiioModule(const std::string &purpose) {
    static std::once_flag once;
    static LoadResult result;
    std::call_once(once, [] { result = load(); });
    if (!result.api) throw std::runtime_error("cannot " + purpose + ": " + result.failure);
    return *result.api;
}

}  // namespace rt
