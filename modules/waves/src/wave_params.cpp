#include "fowtsim/waves/wave_params.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"

namespace fowtsim::waves {
namespace {

struct Problem {
  std::string keys;     // deck keys concerned, e.g. "waves.dt_s"
  std::string message;  // what is wrong, with the value found and what was expected
};

bool finite(double v) { return std::isfinite(v); }

// Record samples N = D/dt when D is a whole multiple of dt (relative slack 1e-9), else empty.
std::optional<double> whole_samples(double duration_s, double dt_s) {
  const double n = std::round(duration_s / dt_s);
  if (n < 1.0 || std::abs(n * dt_s - duration_s) > 1e-9 * duration_s) return std::nullopt;
  return n;
}

}  // namespace

double default_peak_shape(double hs_m, double tp_s) {
  if (!(hs_m > 0.0)) return 1.0;
  const double ratio = tp_s / std::sqrt(hs_m);  // Tp/√Hs [s/√m], IEC 61400-3 Annex B
  if (ratio <= 3.6) return 5.0;
  if (ratio <= 5.0) return std::exp(5.75 - 1.15 * ratio);
  return 1.0;
}

double peak_shape(const WaveParams& p) {
  if (p.model != WaveModel::jonswap) return 1.0;
  return p.gamma ? *p.gamma : default_peak_shape(p.hs_m, p.tp_s);
}

void validate(const WaveParams& p) {
  std::vector<Problem> problems;
  const auto add = [&](std::string keys, std::string message) {
    problems.push_back({std::move(keys), std::move(message)});
  };

  if (!(finite(p.gravity_m_s2) && p.gravity_m_s2 > 0.0))
    add("waves.gravity_m_s2", fmt::format("expected a number > 0, found {}", p.gravity_m_s2));
  if (!(finite(p.water_density_kg_m3) && p.water_density_kg_m3 > 0.0))
    add("waves.water_density_kg_m3", fmt::format("expected a number > 0, found {}", p.water_density_kg_m3));
  if (!(p.depth_m > 0.0))  // +inf allowed (deep water); NaN fails
    add("waves.depth_m", fmt::format("expected a water depth > 0 (or .inf for deep water), found {}", p.depth_m));
  if (!finite(p.heading_deg))
    add("waves.heading_deg", fmt::format("expected a finite angle, found {}", p.heading_deg));
  if (p.elevation_probes_m.empty() || p.elevation_probes_m.size() > kMaxElevationProbes)
    add("waves.elevation_probes_m",
        fmt::format("expected 1 to {} (x, y) points, found {}", kMaxElevationProbes, p.elevation_probes_m.size()));
  for (std::size_t i = 0; i < p.elevation_probes_m.size(); ++i) {
    if (!finite(p.elevation_probes_m[i][0]) || !finite(p.elevation_probes_m[i][1]))
      add(fmt::format("waves.elevation_probes_m[{}]", i), "expected finite coordinates");
  }

  const bool dt_ok = finite(p.dt_s) && p.dt_s > 0.0;
  if (p.model != WaveModel::still && p.model != WaveModel::elevation_series && !dt_ok)
    add("waves.dt_s", fmt::format("expected a time step > 0, found {}", p.dt_s));

  if (p.model == WaveModel::regular) {
    if (!(finite(p.height_m) && p.height_m >= 0.0))
      add("waves.height_m", fmt::format("expected a wave height >= 0, found {}", p.height_m));
    if (!(finite(p.period_s) && p.period_s > 0.0))
      add("waves.period_s", fmt::format("expected a wave period > 0, found {}", p.period_s));
    else if (dt_ok && p.period_s < 2.0 * p.dt_s)
      add("waves.period_s, waves.dt_s",
          fmt::format("time step too coarse for the wave: period {} s < 2 dt_s = {} s (Nyquist); "
                      "use dt_s <= {} s (10 or more steps per period recommended)",
                      p.period_s, 2.0 * p.dt_s, p.period_s / 2.0));
    if (!finite(p.phase_deg))
      add("waves.phase_deg", fmt::format("expected a finite phase, found {}", p.phase_deg));
  }

  if (p.model == WaveModel::jonswap || p.model == WaveModel::pierson_moskowitz) {
    if (!(finite(p.hs_m) && p.hs_m >= 0.0))
      add("waves.hs_m", fmt::format("expected a significant wave height >= 0, found {}", p.hs_m));
    const bool tp_ok = finite(p.tp_s) && p.tp_s > 0.0;
    if (!tp_ok) add("waves.tp_s", fmt::format("expected a peak period > 0, found {}", p.tp_s));
    if (p.gamma) {
      if (!(finite(*p.gamma) && *p.gamma >= 1.0))
        add("waves.gamma", fmt::format("expected a peak-shape factor >= 1 (JONSWAP), found {}", *p.gamma));
      else if (p.model == WaveModel::pierson_moskowitz && *p.gamma != 1.0)
        add("waves.gamma", fmt::format("model pm has gamma = 1, found {}; use model jonswap for gamma > 1", *p.gamma));
    }
    const bool duration_ok = finite(p.duration_s) && p.duration_s > 0.0;
    if (!duration_ok) add("waves.duration_s", fmt::format("expected a record length > 0, found {}", p.duration_s));
    if (duration_ok && dt_ok) {
      const auto n = whole_samples(p.duration_s, p.dt_s);
      if (!n)
        add("waves.duration_s, waves.dt_s",
            fmt::format("duration_s = {} s must be a whole multiple of dt_s = {} s", p.duration_s, p.dt_s));
      else if (*n < 8.0)
        add("waves.duration_s, waves.dt_s", fmt::format("the record needs at least 8 samples, found {}", *n));
      else if (*n > 2147483647.0)
        add("waves.duration_s, waves.dt_s", fmt::format("the record is too long: {} samples", *n));
      if (tp_ok && p.duration_s <= p.tp_s)
        add("waves.duration_s", fmt::format("the record ({} s) must be longer than the peak period tp_s = {} s",
                                            p.duration_s, p.tp_s));
    }
    if (!(finite(p.cutoff_low_hz) && p.cutoff_low_hz >= 0.0))
      add("waves.cutoff_low_hz", fmt::format("expected a frequency >= 0, found {}", p.cutoff_low_hz));
    if (dt_ok) {
      const double nyquist_hz = 0.5 / p.dt_s;
      if (tp_ok && 1.0 / p.tp_s >= nyquist_hz)
        add("waves.tp_s, waves.dt_s",
            fmt::format("time step too coarse for the spectrum: peak 1/tp_s = {} Hz >= Nyquist 1/(2 dt_s) = {} Hz",
                        1.0 / p.tp_s, nyquist_hz));
      const double high = p.cutoff_high_hz ? *p.cutoff_high_hz : nyquist_hz;
      if (p.cutoff_high_hz && !(finite(high) && high > 0.0))
        add("waves.cutoff_high_hz", fmt::format("expected a frequency > 0, found {}", high));
      else if (p.cutoff_high_hz && high > nyquist_hz * (1.0 + 1e-12))
        add("waves.cutoff_high_hz, waves.dt_s",
            fmt::format("time step too coarse for the cut-off frequency: cutoff_high_hz = {} Hz > Nyquist "
                        "1/(2 dt_s) = {} Hz; use dt_s <= {} s or a lower cut-off",
                        high, nyquist_hz, 0.5 / high));
      else if (finite(p.cutoff_low_hz) && p.cutoff_low_hz >= high)
        add("waves.cutoff_low_hz, waves.cutoff_high_hz",
            fmt::format("expected cutoff_low_hz < cutoff_high_hz ({} Hz), found {} Hz", high, p.cutoff_low_hz));
    }
  }

  if (p.model == WaveModel::elevation_series) {
    // The record sets D and Δt (duration_s, dt_s are not used); only the cut-offs are checked
    // against its Nyquist frequency.
    std::optional<RecordGrid> grid;
    if (!p.elevation_record) {
      add("waves.file", "model elevation_series needs an elevation record (deck key file)");
    } else {
      try {
        grid = check_elevation_record(*p.elevation_record);
      } catch (const InputError& e) {
        add("waves.file", e.message());
      }
    }
    if (!(finite(p.cutoff_low_hz) && p.cutoff_low_hz >= 0.0))
      add("waves.cutoff_low_hz", fmt::format("expected a frequency >= 0, found {}", p.cutoff_low_hz));
    if (p.cutoff_high_hz && !(finite(*p.cutoff_high_hz) && *p.cutoff_high_hz > 0.0))
      add("waves.cutoff_high_hz", fmt::format("expected a frequency > 0, found {}", *p.cutoff_high_hz));
    else if (grid) {
      const double nyquist_hz = 0.5 / grid->step_s;
      const double high = p.cutoff_high_hz ? *p.cutoff_high_hz : nyquist_hz;
      if (high > nyquist_hz * (1.0 + 1e-12))
        add("waves.cutoff_high_hz",
            fmt::format("cutoff_high_hz = {} Hz is above the Nyquist frequency 1/(2 dt) = {} Hz of the record "
                        "(dt = {} s): the record holds nothing above it",
                        high, nyquist_hz, grid->step_s));
      else if (finite(p.cutoff_low_hz) && p.cutoff_low_hz >= high)
        add("waves.cutoff_low_hz, waves.cutoff_high_hz",
            fmt::format("expected cutoff_low_hz < cutoff_high_hz ({} Hz), found {} Hz", high, p.cutoff_low_hz));
    }
  }

  if (problems.empty()) return;
  std::string keys;
  std::string message = problems.size() == 1 ? std::string() : fmt::format("{} problems: ", problems.size());
  for (std::size_t i = 0; i < problems.size(); ++i) {
    keys += (i ? "; " : "") + problems[i].keys;
    message += (i ? "; " : "") + problems[i].keys + ": " + problems[i].message;
  }
  throw InputError({"waves", std::nullopt, keys, "see the waves section of the deck (README of modules/waves)"},
                   message);
}

WaveParams with_elevation_record(WaveParams base, std::span<const double> time_s, std::span<const double> elevation_m,
                                 std::string source) {
  base.model = WaveModel::elevation_series;
  base.elevation_record =
      std::make_shared<const ElevationRecord>(make_elevation_record(time_s, elevation_m, std::move(source)));
  return base;
}

std::string_view to_string(WaveModel model) {
  switch (model) {
    case WaveModel::still: return "still";
    case WaveModel::regular: return "regular";
    case WaveModel::jonswap: return "jonswap";
    case WaveModel::pierson_moskowitz: return "pm";
    case WaveModel::elevation_series: return "elevation_series";
  }
  return "?";
}

std::string_view to_string(Stretching stretching) {
  return stretching == Stretching::wheeler ? "wheeler" : "none";
}

WaveModel parse_wave_model(std::string_view text) {
  for (WaveModel m : {WaveModel::still, WaveModel::regular, WaveModel::jonswap, WaveModel::pierson_moskowitz,
                      WaveModel::elevation_series})
    if (text == to_string(m)) return m;
  throw InputError({"waves", std::nullopt, "waves.model", "one of still, regular, jonswap, pm, elevation_series"},
                   fmt::format("unknown wave model '{}'", text));
}

Stretching parse_stretching(std::string_view text) {
  for (Stretching s : {Stretching::none, Stretching::wheeler})
    if (text == to_string(s)) return s;
  throw InputError({"waves", std::nullopt, "waves.stretching", "one of none, wheeler"},
                   fmt::format("unknown stretching '{}'", text));
}

}  // namespace fowtsim::waves
