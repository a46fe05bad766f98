#pragma once
// Readers of output files into a ChannelTable (column 0 = "Time" [s]): ours (HDF5) and
// OpenFAST's (.out text, .outb binary), so runs can be compared channel by channel (DESIGN.md §8).
// Every reader throws fowtsim::InputError naming the file (and the line, for text) on a missing
// file or bad content; read_hdf5_channels throws fowtsim::Error (module "io.hdf5") if HDF5 fails
// inside a file it could open.
#include <filesystem>

#include "fowtsim/io/channel_table.hpp"

namespace fowtsim::io {

// OpenFAST text output: free header lines, a names line whose first token is "Time", a units line
// "(s) (m) ...", then one whitespace- or tab-separated numeric row per time step (Fortran formats
// including exponents without "E" such as 1.0-100 and "D" exponents).
ChannelTable read_openfast_text(const std::filesystem::path& path);

// OpenFAST binary output (.outb), every FileFmtID that OpenFAST writes: 1 (packed int16 data with
// packed int32 time), 2 (packed int16, uniform time), 3 (float64, uniform time), 4 (as 2, with the
// channel-name length in the file). Values are unpacked to double: (packed - ColOff) / ColScl.
// A file holding more rows than its header's NT (a writer killed between appending rows and
// counting them, see outb_writer.hpp) is read whole when its time step is in the header (FileID
// 2–4), with a warning; a last row cut short is dropped. A description ending in "; Status: …"
// (ours) gives the table's status.
ChannelTable read_openfast_binary(const std::filesystem::path& path);

// Our HDF5 output (see hdf5_writer.hpp): Time, then the other channels in creation order. A file
// left by a crash mid-block may hold datasets of unequal length; all are cut to the shortest.
ChannelTable read_hdf5_channels(const std::filesystem::path& path);

// Dispatches on the extension: .h5/.hdf5, .out, .outb (any letter case); others → InputError.
ChannelTable read_channels(const std::filesystem::path& path);

}  // namespace fowtsim::io
