#include "beamdyn/beamdyn_channels.hpp"

#include <algorithm>
#include <cctype>

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
}

}  // namespace fowtsim::driver
