#pragma once
// Trimmed initial conditions (`sweep.trim` in the spec): each operating case starts from the steady
// operating point of its mean wind instead of the base deck's initial state, so that less of its
// run is start-up transient. The operating point is computed once per wind speed by a steady run
// of the base deck — steady power-law wind at that speed, still water, the deck's own controller —
// whose final `average_s` seconds are averaged: rotor speed, blade pitch, platform position and
// angles, and the tower-top deflection of a flexible tower. The runs are cached with the sweep
// (OUTPUT_DIR/trim/, the same case files as the cases), so a rerun or --collect reads them again;
// they rerun only when their deck changes.
//
// Which cases are trimmed: those with a hub-height wind speed whose controller runs normally —
// not idling or parked (controller.operating_mode) and not with a held rotor. The trim keys come
// first among a case's keys, so a preset's or the spec's own initial conditions still win.
#include <cstdio>
#include <filesystem>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sweep/case_expansion.hpp"
#include "sweep/case_files.hpp"
#include "sweep/sweep_spec.hpp"

namespace fowtsim::driver::sweep {

// The steady operating point at one wind speed.
struct OperatingPoint {
  double rotor_speed_rpm = 0.0;                  // RotSpeed
  double blade_pitch_deg = 0.0;                  // BldPitch1
  std::array<double, 3> platform_position_m{};   // PtfmSurge, PtfmSway, PtfmHeave
  std::array<double, 3> platform_angles_deg{};   // PtfmRoll, PtfmPitch, PtfmYaw
  std::optional<std::array<double, 2>> tower_top_deflection_m;  // TTDspFA, TTDspSS (flexible tower)
};

// The trim runs a sweep needs: one per distinct wind speed of its trimmed cases, named trim_ws<V>.
std::vector<SweepCase> trim_cases(const SweepSpec& spec, const std::vector<SweepCase>& cases);

// Where the trim runs keep their files: OUTPUT_DIR/trim/{decks,cases,logs}.
SweepLayout trim_layout(const SweepLayout& layout);

// The operating point from a trim run's output (its last average_s seconds).
OperatingPoint read_operating_point(const std::filesystem::path& output, const TrimSpec& trim);

// Puts each trimmed case's operating point first among its keys (by wind speed); with
// `settle_rayleigh_ritz_blades` (the base deck has them) the blades start at their static deflection
// there (structure.initial_conditions.blade_deflection: static).
void apply_trim(std::vector<SweepCase>& cases, const std::map<double, OperatingPoint>& points, bool settle_rayleigh_ritz_blades);

// Whether a case is trimmed (see above).
bool is_trimmed(const SweepCase& c);

}  // namespace fowtsim::driver::sweep
