#include "beamdyn/beamdyn_channels.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace fowtsim::driver {

std::vector<ChannelInfo> beamdyn_channels() {
  std::vector<ChannelInfo> c;
  const char* axes = "xyz";
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("RootF") + axes[k] + "r", "N", "force of the beam on its root, root frame", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("RootM") + axes[k] + "r", "N-m", "moment of the beam on its root, about the root, root frame", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("TipTD") + axes[k] + "r", "m", "tip translational deflection, root frame", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("TipRD") + axes[k] + "r", "-", "tip rotation (Wiener-Milenkovic), root frame", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("N1F") + axes[k] + "l", "N", "root section force, local section frame", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("N1M") + axes[k] + "l", "N-m", "root section moment, local section frame", "beam"});
  for (std::size_t i = 0; i < 12; ++i) {  // OpenFAST's names for BeamDyn blade 1 in a coupled run
    ChannelInfo b1 = c[i];
    b1.name = "B1" + b1.name;
    c.push_back(b1);
  }
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("RootF") + axes[k] + "b1", "kN", "blade 1 root force, blade frame (ElastoDyn name)", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("RootM") + axes[k] + "b1", "kN-m", "blade 1 root moment, blade frame (ElastoDyn name)", "beam"});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("TipD") + axes[k] + "b1", "m", "blade 1 tip deflection, blade frame (ElastoDyn name)", "beam"});
  for (int k = 0; k < 2; ++k)
    c.push_back({std::string("TipRD") + axes[k] + "b1", "deg", "blade 1 tip rotation, blade frame (ElastoDyn name)", "beam"});
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
