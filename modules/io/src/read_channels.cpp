#include <algorithm>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"

namespace fowtsim::io {

ChannelTable read_channels(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".h5" || extension == ".hdf5") return read_hdf5_channels(path);
  if (extension == ".out") return read_openfast_text(path);
  if (extension == ".outb") return read_openfast_binary(path);
  throw InputError(
      ErrorContext{"io", std::nullopt, path.string(), "use .h5/.hdf5, .out or .outb"},
      fmt::format("cannot tell the format of '{}' from its extension '{}'", path.string(), extension));
}

}  // namespace fowtsim::io
