#pragma once
// Test-only writer of OpenFAST binary outputs (.outb), so the reader can be checked on every
// FileFmtID without OpenFAST. It mirrors OpenFAST's SUBROUTINE WrBinFAST (NWTC_IO.f90), including
// its float32 scale factors and NINT packing, so the quantisation error is the one real files have.
#include <cstdint>
#include <filesystem>
#include <string>

#include "fowtsim/io/channel_table.hpp"

namespace fowtsim::io::testing {

enum class OutbFormat : std::int16_t {
  with_time = 1,                 // packed int16 data, packed int32 time
  without_time = 2,              // packed int16 data, uniform time (TimeOut1, TimeIncr)
  no_compress_without_time = 3,  // float64 data, uniform time
  chan_len_in = 4,               // as 2, with the name length in the file (OpenFAST's default)
};

// Writes `table` (column 0 = time) to `path`. Names and units longer than 10 characters are cut
// for formats 1-3, as OpenFAST does. Formats 2-4 take the time step from the first two rows.
void write_openfast_binary(const std::filesystem::path& path, const ChannelTable& table,
                           OutbFormat format, const std::string& description = "fowtsim test");

}  // namespace fowtsim::io::testing
