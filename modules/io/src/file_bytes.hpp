#pragma once
// Private helper of the readers: a whole file in memory, read with one fread (fast for the
// 20 MB OpenFAST text outputs, and no iostream per-token cost).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "fowtsim/core/error.hpp"

namespace fowtsim::io::detail {

// Why `path` cannot be read as a file ("is a directory", "no such file", …), or "" when it is a
// regular file: a directory named where a file belongs is named as such, not as a missing file.
inline std::string not_a_file_reason(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::regular) return "";
  if (status.type() == std::filesystem::file_type::directory) return "is a directory, not a file";
  if (status.type() == std::filesystem::file_type::not_found) return "no such file";
  return "is not a regular file";
}

inline std::string read_file_bytes(const std::filesystem::path& path, const std::string& module) {
  const std::string name = path.string();
  const auto fail = [&](const std::string& message) {
    throw InputError(ErrorContext{module, std::nullopt, name, "check the path"}, message);
  };
  if (const std::string reason = not_a_file_reason(path); !reason.empty()) fail("'" + name + "' " + reason);
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (error) fail("cannot get the size of '" + name + "'");
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) fail("cannot open '" + name + "'");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (std::fread(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) {
    fail("cannot read '" + name + "'");
  }
  return bytes;
}

}  // namespace fowtsim::io::detail
