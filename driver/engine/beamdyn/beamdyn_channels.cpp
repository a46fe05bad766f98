#include "beamdyn/beamdyn_channels.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace fowtsim::driver {

std::vector<ChannelInfo> beamdyn_channels() {
  struct Group {
    const char* prefix;
    const char* suffix;
    int axes;
    const char* unit;
    const char* description;
  };
  // Order matters: beamdyn_channel_values() fills the same order.
  static constexpr Group kGroups[] = {
      {"RootF", "r", 3, "N", "force of the beam on its root, root frame"},
      {"RootM", "r", 3, "N-m", "moment of the beam on its root, about the root, root frame"},
      {"TipTD", "r", 3, "m", "tip translational deflection, root frame"},
      {"TipRD", "r", 3, "-", "tip rotation (Wiener-Milenkovic), root frame"},
      {"N1F", "l", 3, "N", "root section force, local section frame"},
      {"N1M", "l", 3, "N-m", "root section moment, local section frame"},
      {"B1RootF", "r", 3, "N", "blade 1 root force, root frame (OpenFAST's name for BeamDyn's RootF)"},
      {"B1RootM", "r", 3, "N-m", "blade 1 root moment, root frame (OpenFAST's name for BeamDyn's RootM)"},
      {"B1TipTD", "r", 3, "m", "blade 1 tip deflection, root frame (OpenFAST's name for BeamDyn's TipTD)"},
      {"B1TipRD", "r", 3, "-", "blade 1 tip rotation, root frame (OpenFAST's name for BeamDyn's TipRD)"},
      {"RootF", "b1", 3, "kN", "blade 1 root force, blade frame (ElastoDyn name)"},
      {"RootM", "b1", 3, "kN-m", "blade 1 root moment, blade frame (ElastoDyn name)"},
      {"TipD", "b1", 3, "m", "blade 1 tip deflection, blade frame (ElastoDyn name)"},
      {"TipRD", "b1", 2, "deg", "blade 1 tip rotation, blade frame (ElastoDyn name)"},
  };
  std::vector<ChannelInfo> c;
  for (const Group& g : kGroups)
    for (int k = 0; k < g.axes; ++k)
      c.push_back({std::string(g.prefix) + "xyz"[k] + g.suffix, g.unit, g.description, "beam"});
  return c;
}

std::optional<std::size_t> find_beamdyn_channel(const std::string& name) {
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
    return s;
  };
  const auto all = beamdyn_channels();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (lower(all[i].name) == lower(name)) return i;
  return std::nullopt;
}

void beamdyn_channel_values(const beam::BeamModel& model, const beam::BeamOutputs& out, std::vector<double>& v) {
  v.clear();
  for (int k = 0; k < 6; ++k) v.push_back(out.root_load[k]);
  for (int k = 0; k < 3; ++k) v.push_back(out.tip_displacement_m[k]);
  for (int k = 0; k < 3; ++k) v.push_back(out.tip_rotation_wm[k]);
  // The root section is clamped: its deflected frame is its undeformed (twisted) frame.
  const Mat3 rt = model.root_orientation.transpose();
  const Vec3 f = rt * out.root_load.head<3>(), m = rt * out.root_load.tail<3>();
  for (int k = 0; k < 3; ++k) v.push_back(f[k]);
  for (int k = 0; k < 3; ++k) v.push_back(m[k]);
  for (std::size_t i = 0; i < 12; ++i) v.push_back(v[i]);  // B1-prefixed copies
  for (int k = 0; k < 6; ++k) v.push_back(1e-3 * out.root_load[k]);
  for (int k = 0; k < 3; ++k) v.push_back(out.tip_displacement_m[k]);
  // Rotation vector of the tip rotation in degrees (ElastoDyn reports small angles; the WM
  // parameters c = 4 tan(φ/4) n convert exactly to φ n).
  const double c = out.tip_rotation_wm.norm();
  const Vec3 phi = c > 0.0 ? Vec3(4.0 * std::atan(0.25 * c) / c * out.tip_rotation_wm) : Vec3::Zero();
  for (int k = 0; k < 2; ++k) v.push_back(phi[k] * 180.0 / 3.14159265358979323846);
}

}  // namespace fowtsim::driver
