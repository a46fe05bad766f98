#pragma once
// Wave kinematics precomputed on the fixed points a scene needs (e.g. hydrodynamic strip nodes at
// their mean positions): time series built once by inverse FFT (one per point and quantity), so a
// lookup during the run is an interpolation in time — no FFT, no allocation, no summation.
//
// Storage, per distinct (x, y) column: η(t). Per point:
//   stretching none:    u_h, w, a_h, a_z, p_d at the point's z (exact on the samples); nothing for
//                       z > 0 (always dry).
//   stretching wheeler: per column, the unstretched field at levels z'_l from 0 down to below the
//                       lowest z' its points reach (z' = h(z − η_max)/(h + η_max)); level spacing
//                       Δ0 = surface_spacing / k_max at the top (k_max: highest wavenumber present),
//                       growing as max(Δ0, growth·|z'|) below, plus two levels for the stencil. A
//                       lookup maps z to z' with the interpolated η and interpolates cubically
//                       (4-point Lagrange) in z'. Each component's amplitude decays as e^{kz'}, so
//                       geometric spacing bounds every component's error by ≈ 0.023 (k Δ)⁴ e^{k z'}
//                       of its surface amplitude: ≤ 6e-5 below (growth 0.15), ≤ 1e-4 at the top
//                       (0.25); measured ≤ 1.5e-4 of the RMS on the extreme OC3 sea.
// In time: 4-point cubic Lagrange on the periodic record; for a component of frequency ω the error
// is at most (9/16)/24 (ω Δt)⁴ of its amplitude, 0.9 % at 8 samples per period. The stored step
// Δt = dt_s / m: by default m is chosen so that the highest frequency present gets at least 8
// samples per period (with the default cut-off at Nyquist, m = 4). Accelerations need this: their
// spectrum ω⁴ S(ω) ~ 1/ω carries much of its variance near the cut-off.
// Horizontal vectors are e·u_h, e·a_h (unidirectional sea).
#include <cstddef>
#include <span>
#include <vector>

#include "fowtsim/core/interpolation.hpp"
#include "fowtsim/core/types.hpp"
#include "fowtsim/waves/wave_field.hpp"

namespace fowtsim::waves {

struct PrecomputeOptions {
  std::size_t oversampling = 0;       // stored samples per record step m (zero-padded FFT: the
                                      //   band-limited interpolant); 0 = automatic (below) [-]
  double samples_per_shortest_period = 8.0;  // automatic m: smallest m giving the highest
                                      //   frequency present this many samples per period [-]
  bool elevation_only = false;        // store η only (elevation probes); at() then returns η only
  double wheeler_surface_spacing = 0.25;  // Δ0 · k_max at the top level [-] (> 0)
  double wheeler_growth = 0.15;       // level spacing / |z'| below the surface [-] (> 0)
};

class PrecomputedKinematics {
 public:
  // Builds every series (the expensive part: O(points · quantities · N log N)). Throws InputError for
  // points below the seabed (beyond round-off; at round-off they sit on it), non-finite
  // coordinates or bad options.
  PrecomputedKinematics(const WaveField& field, std::span<const Vec3> points_m,
                        const PrecomputeOptions& options = {});

  std::size_t size() const { return points_.size(); }             // number of points
  const Vec3& point(std::size_t index) const { return points_.at(index).position_m; }
  std::size_t samples() const { return samples_; }                // stored samples per record
  double sample_dt_s() const { return dt_s_; }                     // D / samples [s]
  double record_duration_s() const { return duration_s_; }        // D [s]; lookups wrap modulo D
  std::size_t memory_bytes() const { return storage_.capacity() * sizeof(double); }
  std::size_t wheeler_levels(std::size_t index) const;            // levels of the point's column (0: none)

  // Kinematics at point `index` at time t (any t; the record repeats with period D). Allocation
  // free. Throws std::out_of_range for a bad index, NumericalError for non-finite t.
  WaveKinematics at(std::size_t index, double t_s) const;
  // η only.
  double elevation(std::size_t index, double t_s) const;
  // The same at the time of `stencil(t_s)`: every point of one evaluation shares the time's stencil
  // (the lookups above compute it per point). Bit-identical to at(index, t_s), elevation(index, t_s).
  PeriodicStencil stencil(double t_s) const { return periodic_cubic_stencil(t_s, duration_s_, samples_); }
  WaveKinematics at(std::size_t index, const PeriodicStencil& time) const;
  double elevation(std::size_t index, const PeriodicStencil& time) const;

 private:
  struct Column {
    std::size_t elevation_offset = 0;      // start of η(t) in storage_
    std::vector<double> levels_m;          // Wheeler: ascending z' levels (last = 0)
    std::size_t level_offset = 0;          // Wheeler: start of [sample][level][quantity] block
  };
  enum class PointKind { dry, exact, wheeler };
  struct Point {
    Vec3 position_m = Vec3::Zero();
    std::size_t column = 0;
    PointKind kind = PointKind::dry;
    std::size_t offset = 0;                // exact: start of [sample][quantity] block
  };
  double interpolate_elevation(const Column& column, const PeriodicStencil& ts) const;

  std::vector<Point> points_;
  std::vector<Column> columns_;
  std::vector<double> storage_;
  Vec3 direction_ = Vec3::UnitX();
  double depth_m_ = 0.0;
  Stretching stretching_ = Stretching::none;
  bool elevation_only_ = false;
  std::size_t samples_ = 0;
  double dt_s_ = 0.0;
  double duration_s_ = 0.0;
};

}  // namespace fowtsim::waves
