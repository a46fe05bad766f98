#pragma once
// BeamDyn's output channels (names, units, frames as the BeamDyn driver writes them), computed
// from the beam's outputs. r: the rotating root frame (the beam's floating frame f); l: the
// deflected local section frame.
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/beam/beam_model.hpp"
#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/beam_state.hpp"
#include "fowtsim/core/channels.hpp"

namespace fowtsim::driver {

// The channels we can write:
//  * BeamDyn's (N, N-m, m, WM parameters): RootF/M{x,y,z}r, TipTD/TipRD{x,y,z}r, N1F/M{x,y,z}l;
//  * the same as OpenFAST names BeamDyn's channels of blade 1 in a coupled run: B1RootFxr, …;
//  * ElastoDyn's blade-frame names (frame b: the pitched blade root frame, which is r here):
//    RootF/M{x,y,z}b1 in kN, kN-m; TipD{x,y,z}b1 in m; TipRD{x,y}b1 in deg (rotation vector).
std::vector<ChannelInfo> beamdyn_channels();

// Index into beamdyn_channels() of a BeamDyn channel name (case-insensitive), if we support it.
std::optional<std::size_t> find_beamdyn_channel(const std::string& name);

// Values of all beamdyn_channels(), in that order, into `values` (resized once).
void beamdyn_channel_values(const beam::BeamModel& model, const beam::BeamOutputs& out, std::vector<double>& values);

}  // namespace fowtsim::driver
