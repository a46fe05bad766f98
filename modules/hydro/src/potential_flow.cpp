#include "fowtsim/hydro/potential_flow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "fowtsim/hydro/radiation_kernel.hpp"

namespace fowtsim::hydro {
namespace {

// Largest |B_ij(ω)| over the table.
Mat6 peak_damping(const RadiationTable& table) {
  Mat6 peak = Mat6::Zero();
  for (const Mat6& b : table.damping) peak = peak.cwiseMax(b.cwiseAbs());
  return peak;
}

// Entries worth a kernel: off the diagonal above 1e-6 of the geometric mean of their diagonals,
// on it above 1e-6 of the largest diagonal of the same kind (translations 0–2, rotations 3–5 share
// units). Below that a WAMIT table holds round-off (e.g. the yaw of an axisymmetric spar).
bool significant(const Mat6& peak, int i, int j) {
  if (i != j) return peak(i, j) > 1e-6 * std::sqrt(peak(i, i) * peak(j, j));
  const int first = i < 3 ? 0 : 3;
  return peak(i, i) > 0.0 && peak(i, i) > 1e-6 * peak.diagonal().segment<3>(first).maxCoeff();
}

// φ₁(z) = (e^z − 1)/z and φ₂(z) = (e^z − 1 − z)/z², by their series where the closed forms
// cancel (|z| < 0.05: truncation below 1e-12 of the value, round-off of the closed form below 1e-13).
void phi_functions(std::complex<double> z, std::complex<double>& phi1, std::complex<double>& phi2) {
  if (std::abs(z) < 0.05) {
    phi1 = 1.0 + z * (1.0 / 2.0 + z * (1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z / 720.0))));
    phi2 = 0.5 + z * (1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z * (1.0 / 720.0 + z / 5040.0))));
    return;
  }
  const std::complex<double> e = std::exp(z);
  phi1 = (e - 1.0) / z;
  phi2 = (e - 1.0 - z) / (z * z);
}

// ξ(t_n + h) for velocity v0 at t_n and v1 at t_n + h, linear in between.
std::complex<double> modal_update(std::complex<double> pole, std::complex<double> xi, double h, double v0, double v1) {
  if (h == 0.0) return xi;
  std::complex<double> phi1, phi2;
  phi_functions(pole * h, phi1, phi2);
  return std::exp(pole * h) * xi + h * ((phi1 - phi2) * v0 + phi2 * v1);
}

// Σ_s w_s K(h + sΔT) q̇(t_n − sΔT) over the stored history (trapezoid weights ΔT/2 at both ends),
// for h = (base + frac) ΔT/2 with frac = 0 and each base in `bases`, or one off-grid h: the memory
// integral but for its newest interval [t_n, t_n + h]. One pass over the history, newest first
// (no modulo per sample), serving every entry and every requested h.
template <int kStages>
void history_sums(const RadiationModel& model, const RadiationState& state, const int (&bases)[kStages], double frac,
                  Vec6 (&out)[kStages]) {
  const auto entries = static_cast<int>(model.entries.size());
  constexpr int kMaxEntries = 36;
  double sum[kStages][kMaxEntries] = {};
  int col[kMaxEntries];
  for (int e = 0; e < entries; ++e) col[e] = model.entries[static_cast<std::size_t>(e)].col;
  const double dt = model.step_s;
  const int n = model.window_steps;
  const auto size = static_cast<int>(state.history.size());
  int index = state.newest;
  for (int s = 0; s <= n; ++s) {
    const Vec6 x = ((s == 0 || s == n) ? 0.5 * dt : dt) * state.history[static_cast<std::size_t>(index)];
    for (int stage = 0; stage < kStages; ++stage) {
      const double* k = model.kernel.data() + static_cast<std::size_t>((2 * s + bases[stage]) * entries);
      if (frac == 0.0) {
        for (int e = 0; e < entries; ++e) sum[stage][e] += k[e] * x[col[e]];
      } else {
        for (int e = 0; e < entries; ++e) sum[stage][e] += ((1.0 - frac) * k[e] + frac * k[e + entries]) * x[col[e]];
      }
    }
    index = index == 0 ? size - 1 : index - 1;
  }
  for (int stage = 0; stage < kStages; ++stage) {
    out[stage].setZero();
    for (int e = 0; e < entries; ++e) out[stage][model.entries[static_cast<std::size_t>(e)].row] -= sum[stage][e];
  }
}

// The three on-grid history parts (h = 0, ΔT/2, ΔT), summed directly (at the start).
void update_history_loads(const RadiationModel& model, RadiationState& state) {
  constexpr int bases[3] = {0, 1, 2};
  Vec6 out[3];
  history_sums(model, state, bases, 0.0, out);
  for (int stage = 0; stage < 3; ++stage) state.history_load[static_cast<std::size_t>(stage)] = out[stage];
}

// One step on: the new h = 0 part follows from the old h = ΔT part, which holds the same products
// K((s + 1)ΔT) q̇_{n−s} but for the trapezoid's end weights and the window's ends:
//   S₀(n+1) = S_ΔT(n) + ½ΔT [K(0) q̇_{n+1} + K(ΔT) q̇_n − K(NΔT) q̇_{n−N+1} − K((N+1)ΔT) q̇_{n−N}]
// (S the sums, the loads −S). S_ΔT is summed directly every step, so nothing accumulates; the
// ΔT/2 and ΔT parts are summed anew in one pass. `velocity` is q̇_{n+1}, not yet in the ring.
void step_history_loads(const RadiationModel& model, const Vec6& velocity, RadiationState& state) {
  const auto size = static_cast<int>(state.history.size());
  const int n = model.window_steps;
  const Vec6& newest = state.history[static_cast<std::size_t>(state.newest)];                       // q̇_n
  const Vec6& oldest = state.history[static_cast<std::size_t>((state.newest + 1) % size)];          // q̇_{n−N}
  const Vec6& second_oldest = state.history[static_cast<std::size_t>((state.newest + 2) % size)];   // q̇_{n−N+1}
  const std::size_t entries = model.entries.size();
  const auto k = [&](int j, std::size_t e) { return model.kernel[static_cast<std::size_t>(2 * j) * entries + e]; };
  Vec6 h0 = state.history_load[2];
  for (std::size_t e = 0; e < entries; ++e) {
    const int c = model.entries[e].col;
    h0[model.entries[e].row] -= 0.5 * model.step_s *
                                (k(0, e) * velocity[c] + k(1, e) * newest[c] - k(n, e) * second_oldest[c] - k(n + 1, e) * oldest[c]);
  }
  state.newest = (state.newest + 1) % size;
  state.history[static_cast<std::size_t>(state.newest)] = velocity;
  constexpr int bases[2] = {1, 2};
  Vec6 out[2];
  history_sums(model, state, bases, 0.0, out);
  state.history_load = {h0, out[0], out[1]};
}

}  // namespace

RadiationModel make_radiation_model(const RadiationTable& table, const RadiationOptions& options) {
  if (!(options.step_s > 0.0) || !(options.window_s > options.step_s) || !(options.fit_tolerance > 0.0) ||
      options.fit_max_order < 2)
    throw InputError({"hydro.potential_flow", std::nullopt, "radiation options",
                      "step > 0, window > step, fit tolerance > 0, max order ≥ 2"},
                     fmt::format("radiation step {} s, window {} s, tolerance {}, max order {}", options.step_s,
                                 options.window_s, options.fit_tolerance, options.fit_max_order));
  RadiationModel model;
  model.method = options.method;
  model.step_s = options.step_s;
  model.window_steps = static_cast<int>(std::ceil(options.window_s / options.step_s - 1e-9));
  model.added_mass_infinite_frequency = table.added_mass_infinite_frequency;
  model.fit_tolerance = options.fit_tolerance;
  // Kernel at ΔT/2 over the window and the two half steps a stage can add.
  const double half = 0.5 * options.step_s;
  std::vector<double> times(static_cast<std::size_t>(2 * model.window_steps + 3));
  for (std::size_t k = 0; k < times.size(); ++k) times[k] = half * static_cast<double>(k);
  const std::vector<Mat6> kernel = retardation_kernel(table.frequencies_rad_s, table.damping, times);
  const Mat6 peak = peak_damping(table);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      if (!significant(peak, i, j)) continue;
      RadiationEntry e;
      e.row = i;
      e.col = j;
      double peak = 0.0, tail = 0.0;
      const auto last_second = static_cast<std::size_t>(std::max(0.0, 2.0 * model.window_steps - 2.0 / options.step_s));
      for (std::size_t k = 0; k <= static_cast<std::size_t>(2 * model.window_steps); ++k) {
        peak = std::max(peak, std::abs(kernel[k](i, j)));
        if (k >= last_second) tail = std::max(tail, std::abs(kernel[k](i, j)));
      }
      e.tail_ratio = peak > 0.0 ? tail / peak : 0.0;
      if (model.method == RadiationMethod::state_space) {
        std::vector<double> samples_ij(times.size());
        for (std::size_t k = 0; k < times.size(); ++k) samples_ij[k] = kernel[k](i, j);
        // Fitted on the window, thinned to at most 400 samples: the Hankel matrices stay 200 × 200
        // (an SVD of well under a second) and the kernel's shortest feature, ~1 s for a spar, keeps
        // ≥ 6 samples per second for any window up to 60 s.
        const std::size_t window = static_cast<std::size_t>(2 * model.window_steps + 1);
        const std::size_t stride = (window + 399) / 400;
        std::vector<double> samples;
        for (std::size_t k = 0; k < window; k += stride) samples.push_back(samples_ij[k]);
        e.fit = fit_exponentials(samples, half * static_cast<double>(stride), options.fit_tolerance, options.fit_max_order);
        e.first_term = model.term_count;
        model.term_count += static_cast<int>(e.fit.terms.size());
      }
      model.entries.push_back(std::move(e));
    }
  if (model.method == RadiationMethod::convolution) {
    const std::size_t entries = model.entries.size();
    model.kernel.resize(times.size() * entries);
    for (std::size_t k = 0; k < times.size(); ++k)
      for (std::size_t e = 0; e < entries; ++e)
        model.kernel[k * entries + e] = kernel[k](model.entries[e].row, model.entries[e].col);
  }
  return model;
}

RadiationState make_radiation_state(const RadiationModel& model, double t0_s, const Vec6& velocity) {
  RadiationState s;
  s.time_s = t0_s;
  s.velocity = velocity;
  if (model.method == RadiationMethod::convolution) {
    s.history.assign(static_cast<std::size_t>(model.window_steps + 1), Vec6::Zero());
    s.history[0] = velocity;
    update_history_loads(model, s);
  } else {
    s.modal.assign(static_cast<std::size_t>(model.term_count), 0.0);
  }
  return s;
}

Vec6 radiation_load(const RadiationModel& model, const RadiationState& state, double t_s, const Vec6& velocity) {
  const double h = t_s - state.time_s;
  const double dt = model.step_s;
  if (!(h >= -1e-9 * dt && h <= dt * (1.0 + 1e-9)))
    throw std::logic_error(fmt::format("radiation_load at t = {} s outside the step from t_n = {} s", t_s, state.time_s));
  Vec6 force = Vec6::Zero();
  if (model.method == RadiationMethod::state_space) {
    for (const RadiationEntry& e : model.entries) {
      double sum = 0.0;
      for (std::size_t m = 0; m < e.fit.terms.size(); ++m) {
        const ExponentialTerm& term = e.fit.terms[m];
        const std::complex<double> xi = modal_update(term.pole, state.modal[static_cast<std::size_t>(e.first_term) + m],
                                                     std::max(h, 0.0), state.velocity[e.col], velocity[e.col]);
        sum += term.weight * (term.residue * xi).real();
      }
      force[e.row] -= sum;
    }
    return force;
  }
  // Trapezoidal rule: the newest interval [t_n, t] (width h) with the stage velocity, then the
  // history intervals of ΔT. Kernel sample index of τ = h + kΔT is (position + 2k), interpolated
  // linearly off the half-step grid; on it (every RK4 stage) the history part is the stored one.
  const double position = std::clamp(h / (0.5 * dt), 0.0, 2.0);
  const int base = std::min(static_cast<int>(std::floor(position)), 1);
  const double frac = position - base;
  const double on_grid = std::round(position);
  if (std::abs(position - on_grid) < 1e-9) {
    force = state.history_load[static_cast<std::size_t>(on_grid)];
  } else {
    const int bases[1] = {base};
    Vec6 off_grid[1];
    history_sums(model, state, bases, frac, off_grid);
    force = off_grid[0];
  }
  const std::size_t entries = model.entries.size();
  for (std::size_t e = 0; e < entries; ++e) {
    const RadiationEntry& entry = model.entries[e];
    const double k_0 = model.kernel[e];
    const double k_h = (1.0 - frac) * model.kernel[static_cast<std::size_t>(base) * entries + e] +
                       frac * model.kernel[static_cast<std::size_t>(base + 1) * entries + e];
    force[entry.row] -= 0.5 * std::max(h, 0.0) * (k_0 * velocity[entry.col] + k_h * state.velocity[entry.col]);
  }
  return force;
}

void advance_radiation(const RadiationModel& model, double t_end_s, const Vec6& velocity, RadiationState& state) {
  const double dt = t_end_s - state.time_s;
  if (std::abs(dt - model.step_s) > 1e-9 * model.step_s)
    throw std::logic_error(fmt::format("advance_radiation over {} s, the model's step is {} s", dt, model.step_s));
  if (model.method == RadiationMethod::state_space) {
    for (const RadiationEntry& e : model.entries)
      for (std::size_t m = 0; m < e.fit.terms.size(); ++m) {
        std::complex<double>& xi = state.modal[static_cast<std::size_t>(e.first_term) + m];
        xi = modal_update(e.fit.terms[m].pole, xi, model.step_s, state.velocity[e.col], velocity[e.col]);
      }
  } else {
    step_history_loads(model, velocity, state);
  }
  state.velocity = velocity;
  state.time_s = t_end_s;
}

}  // namespace fowtsim::hydro
