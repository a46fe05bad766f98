#include "verify/beamdyn_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/readers.hpp"
#include "run/run_scene.hpp"

namespace fowtsim::driver {
namespace {

const std::vector<double>& column(const io::ChannelTable& t, std::string_view channel) {
  const auto i = t.find(channel);
  if (!i) throw Error({"verify", {}, std::string(channel), ""}, "channel " + std::string(channel) + " not in the table");
  return t.columns[*i];
}

double interpolate(const std::vector<double>& t, const std::vector<double>& y, double at) {
  const auto hi = std::clamp<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin(), 1, t.size() - 1);
  const double w = (at - t[hi - 1]) / (t[hi] - t[hi - 1]);
  return (1.0 - w) * y[hi - 1] + w * y[hi];
}

struct Moments {
  double mean = 0.0, std = 0.0, rms = 0.0;
};
Moments moments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) {
    m.mean += x;
    m.rms += x * x;
  }
  m.mean /= v.size();
  m.rms = std::sqrt(m.rms / v.size());
  m.std = std::sqrt(std::max(0.0, m.rms * m.rms - m.mean * m.mean));
  return m;
}

}  // namespace

BeamDynRun run_beamdyn_reference(const std::filesystem::path& driver_inp, const std::filesystem::path& reference_out,
                                 int segments, const std::filesystem::path& output_base,
                                 const std::optional<std::string>& integrator,
                                 const std::optional<int>& matrix_max_age) {
  RunRequest request;
  request.deck_path = driver_inp;
  request.output_base = output_base;
  request.output_format = "out";
  request.beam_segments = segments;
  request.beam_integrator = integrator;
  request.beam_matrix_max_age = matrix_max_age;
  const RunReport report = run_scene(request, {});
  BeamDynRun run;
  run.ours = io::read_channels(output_base.string() + ".out");
  run.reference = io::read_channels(reference_out);
  run.wall_s = report.wall_s;
  run.simulated_s = report.simulated_s;
  return run;
}

double final_value(const io::ChannelTable& table, std::string_view channel) { return column(table, channel).back(); }

SignalComparison compare_signal(const BeamDynRun& run, std::string_view channel, double t_from) {
  const std::vector<double>& t_ref = run.reference.time();
  const std::vector<double>& y_ref = column(run.reference, channel);
  const std::vector<double>& t_ours = run.ours.time();
  const std::vector<double>& y_ours = column(run.ours, channel);
  std::vector<double> ref, ours, diff;
  for (std::size_t i = 0; i < t_ref.size(); ++i) {
    if (t_ref[i] < t_from - 1e-9 || t_ref[i] > t_ours.back() + 1e-9) continue;
    ref.push_back(y_ref[i]);
    ours.push_back(interpolate(t_ours, y_ours, t_ref[i]));
    diff.push_back(ours.back() - ref.back());
  }
  const Moments r = moments(ref), o = moments(ours), d = moments(diff);
  return {d.rms / r.rms, d.std / r.std, o.mean, r.mean, o.std, r.std};
}

}  // namespace fowtsim::driver
