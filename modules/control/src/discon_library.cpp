#include <dlfcn.h>

#include <fmt/format.h>

#include "fowtsim/control/external_controller.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::control {
namespace {

std::string loader_message() {
  const char* message = dlerror();
  return message ? message : "no message from the loader";
}

}  // namespace

DisconLibrary::DisconLibrary(const std::string& path, const std::string& procedure) : path_(path) {
  dlerror();  // clear a stale message
  handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    throw InputError({"control.dll", std::nullopt, "controller.library_path",
                      "give the path of a shared library built for this platform"},
                     fmt::format("cannot load the controller library '{}': {}", path, loader_message()));
  }
  dlerror();
  void* symbol = dlsym(handle_, procedure.c_str());
  if (!symbol) {
    const std::string why = loader_message();
    dlclose(handle_);
    throw InputError({"control.dll", std::nullopt, "controller.procedure",
                      "export the procedure with C linkage (extern \"C\" / BIND(C)) or fix the name"},
                     fmt::format("controller library '{}' has no procedure '{}': {}", path, procedure, why));
  }
  // POSIX guarantees that a data pointer from dlsym converts to a function pointer.
  procedure_ = reinterpret_cast<DisconProcedure>(symbol);
}

DisconLibrary::~DisconLibrary() {
  if (handle_) dlclose(handle_);
}

}  // namespace fowtsim::control
