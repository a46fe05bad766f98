// Output channels with OpenFAST AeroDyn names, units and signs (AeroDyn OutListParameters):
// rotor quantities Rt…, and per blade (B1…B3) and output node (N1…N9 = output_nodes entries, as
// AeroDyn's BlOutNd) the section quantities.
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "fowtsim/aero/aero.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::aero {
namespace {

constexpr double kDegree = 180.0 / std::numbers::pi;
constexpr double kRpm = 30.0 / std::numbers::pi;

struct RotorChannel {
  const char* name;
  const char* unit;
  const char* description;
};

constexpr RotorChannel kRotor[] = {
    {"RtSpeed", "rpm", "rotor speed about the shaft x_h"},
    {"RtTSR", "-", "tip-speed ratio Omega R / RtVAvgxh"},
    {"RtVAvgxh", "m/s", "disk-mean relative inflow along x_h"},
    {"RtSkew", "deg", "inflow skew: angle between disk-mean inflow and x_h"},
    {"RtArea", "m^2", "swept area pi R^2, R = largest node distance from the shaft axis"},
    {"RtAeroCp", "-", "aerodynamic power coefficient RtAeroPwr / (rho/2 A U^3), U = RtVAvgxh"},
    {"RtAeroCq", "-", "torque coefficient RtAeroMxh / (rho/2 A U^2 R)"},
    {"RtAeroCt", "-", "thrust coefficient RtAeroFxh / (rho/2 A U^2)"},
    {"RtAeroPwr", "W", "aerodynamic rotor power Omega RtAeroMxh (before drivetrain losses)"},
    {"RtAeroFxh", "N", "rotor aerodynamic force along x_h (thrust, + downwind)"},
    {"RtAeroFyh", "N", "rotor aerodynamic force along y_h"},
    {"RtAeroFzh", "N", "rotor aerodynamic force along z_h"},
    {"RtAeroMxh", "N-m", "rotor aerodynamic moment about x_h at the hub centre (torque)"},
    {"RtAeroMyh", "N-m", "rotor aerodynamic moment about y_h at the hub centre"},
    {"RtAeroMzh", "N-m", "rotor aerodynamic moment about z_h at the hub centre"},
};
constexpr int kRotorCount = sizeof(kRotor) / sizeof(kRotor[0]);

constexpr RotorChannel kNode[] = {
    {"Alpha", "deg", "angle of attack"},
    {"AxInd", "-", "axial induction a (after the skew redistribution)"},
    {"TnInd", "-", "tangential induction a'"},
    {"Phi", "deg", "inflow angle to the coned rotor plane"},
    {"Vrel", "m/s", "relative speed W in the airfoil section plane"},
    {"Cl", "-", "lift coefficient"},
    {"Cd", "-", "drag coefficient"},
    {"Cm", "-", "pitching-moment coefficient (+ nose up)"},
    {"Fx", "N/m", "force per unit span normal to the coned rotor plane (+ downwind, x_b)"},
    {"Fy", "N/m", "force per unit span in the plane, + in the direction of rotation (-y_b)"},
};
constexpr int kNodeCount = sizeof(kNode) / sizeof(kNode[0]);

int output_blades(const Params& params) { return std::min(params.number_of_blades, 3); }

}  // namespace

std::vector<ChannelInfo> Aero::channels(const Params& params) {
  std::vector<ChannelInfo> list;
  for (const RotorChannel& c : kRotor) list.push_back({c.name, c.unit, c.description, "aero"});
  for (int b = 1; b <= output_blades(params); ++b) {
    for (std::size_t j = 0; j < params.output_nodes.size(); ++j) {
      for (const RotorChannel& c : kNode) {
        list.push_back({fmt::format("B{}N{}{}", b, j + 1, c.name), c.unit,
                        fmt::format("blade {} node {}: {}", b, params.output_nodes[j], c.description),
                        "aero"});
      }
    }
  }
  return list;
}

void channel_values(const Params& params, const Aero::Input& input, const Aero::Output& out,
                    std::span<double> v) {
  const std::size_t expected =
      kRotorCount + static_cast<std::size_t>(output_blades(params)) * params.output_nodes.size() * kNodeCount;
  if (v.size() != expected) {
    throw InputError({"aero", std::nullopt, "channel values", "size the buffer as channels(params)"},
                     fmt::format("channel buffer has {} entries (expected {})", v.size(), expected));
  }
  const RotorResult& r = out.rotor;
  const double rotor[kRotorCount] = {
      input.rotor_speed_rad_s * kRpm, r.tip_speed_ratio, r.mean_axial_inflow_m_s, r.skew_rad * kDegree,
      r.area_m2, r.cp, r.cq, r.ct, r.power_W, r.force_hub_N.x(), r.force_hub_N.y(), r.force_hub_N.z(),
      r.moment_hub_N_m.x(), r.moment_hub_N_m.y(), r.moment_hub_N_m.z()};
  std::size_t k = 0;
  for (double x : rotor) v[k++] = x;
  const int nn = nodes_per_blade(params);
  for (int b = 0; b < output_blades(params); ++b) {
    for (int node : params.output_nodes) {
      const NodeResult& n = out.nodes[b * nn + node - 1];
      const SectionSolution& s = n.section;
      const double values[kNodeCount] = {s.alpha_rad * kDegree, s.axial_induction, s.tangential_induction,
                                         s.phi_rad * kDegree, s.relative_speed_m_s, s.coefficients.cl,
                                         s.coefficients.cd, s.coefficients.cm, n.normal_force_N_m,
                                         n.tangential_force_N_m};
      for (double x : values) v[k++] = x;
    }
  }
}

}  // namespace fowtsim::aero
