#pragma once
// The module contract of DESIGN.md §2, as a C++20 concept.
//
// A module is a type that names four plain-data types and four pure functions:
//   Params  immutable, built once from the deck and validated there;
//   State   what the module integrates; plain, copyable (retry a step, checkpoint, perturb), with
//           a field list beside it (core/fields.hpp) when it is not trivially copyable;
//   Input   what the driver hands in (motions of attachment points, inflow, commands);
//   Output  what it hands back (loads at attachment points, measured signals, channel values).
// make_state(params)                  -> initial State
// advance(params, input, t, dt, state) advances state from t to t+dt (sub-stepping inside is the
//                                      module's business); throws NumericalError on trouble
// outputs(params, input, state)        -> Output, with no side effect
// channels(params)                     -> the output channels the module can write
// No module owns a clock, a file or a global; no module prints.
#include <concepts>
#include <vector>

#include "fowtsim/core/channels.hpp"

namespace fowtsim {

template <class M>
concept Module = std::copyable<typename M::State> &&
    requires(const typename M::Params& params, const typename M::Input& input,
             typename M::State& state, const typename M::State& const_state, double t,
             double dt) {
      { M::make_state(params) } -> std::same_as<typename M::State>;
      { M::advance(params, input, t, dt, state) } -> std::same_as<void>;
      { M::outputs(params, input, const_state) } -> std::same_as<typename M::Output>;
      { M::channels(params) } -> std::same_as<std::vector<ChannelInfo>>;
    };

}  // namespace fowtsim
