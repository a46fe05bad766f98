#include "fowtsim/wind/full_field.hpp"

#include <cmath>
#include <string>

#include "fowtsim/core/error.hpp"

namespace fowtsim::wind {
namespace {

[[noreturn]] void bad_field(const std::string& variable, const std::string& message) {
  throw InputError(ErrorContext{"wind.full_field", std::nullopt, variable, ""}, message);
}

[[noreturn]] void outside(double time_s, const std::string& message) {
  throw NumericalError(ErrorContext{"wind.full_field", time_s, "query point",
                                    "enlarge the wind grid or shorten the run"},
                       message);
}

// Bracketing time samples and weight of the upper one for the shifted time t' (InflowWind: linear
// in time; a periodic record wraps, so sample nt follows nt−1 by one dt back to sample 0).
struct TimeBracket {
  int lower;
  int upper;
  double weight;
};

TimeBracket bracket_time(const FullField& f, double shifted_s, double time_s) {
  double t = shifted_s;
  if (f.periodic) {
    t = std::fmod(t, f.total_time_s());
    if (t < 0.0) t += f.total_time_s();
  } else if (t < 0.0 || t > f.total_time_s()) {
    outside(time_s, "full-field wind record exhausted: shifted time " + std::to_string(shifted_s) +
                        " s outside [0, " + std::to_string(f.total_time_s()) + "] s");
  }
  const double index = t / f.dt_s;
  int lower = static_cast<int>(std::floor(index));
  double weight = index - lower;
  if (lower >= f.nt - 1 && !f.periodic) {  // the very last sample
    lower = f.nt - 2;
    weight = 1.0;
  }
  if (lower >= f.nt) lower = f.nt - 1;  // fmod rounding at the period
  const int upper = (lower + 1) % f.nt;
  if (f.nt_held == 0) return {lower, upper, weight};
  // Held rows: the record's first nt_held, then its last nt_tail.
  const auto held_row = [&](int it) {
    if (it < f.nt_held) return it;
    if (it >= f.nt - f.nt_tail) return f.nt_held + it - (f.nt - f.nt_tail);
    outside(time_s, "the wind field holds the first " + std::to_string(f.nt_held) + " and the last " + std::to_string(f.nt_tail) +
                        " of its " + std::to_string(f.nt) + " samples, generated for the run's length; shifted time " +
                        std::to_string(shifted_s) + " s needs more");
  };
  return {held_row(lower), held_row(upper), weight};
}

Vec3 grid_sample(const FullField& f, int it, int iz, int iy) {
  const std::size_t i = ((static_cast<std::size_t>(it) * f.nz + iz) * f.ny + iy) * 3;
  return Vec3(f.grid[i], f.grid[i + 1], f.grid[i + 2]);
}

Vec3 tower_sample(const FullField& f, int it, int k) {
  const std::size_t i = (static_cast<std::size_t>(it) * f.n_tower + k) * 3;
  return Vec3(f.tower[i], f.tower[i + 1], f.tower[i + 2]);
}

// Bilinear in y–z at time sample it.
Vec3 grid_bilinear(const FullField& f, int it, int iy, double sy, int iz, double sz) {
  const Vec3 a = grid_sample(f, it, iz, iy) * (1.0 - sy) + grid_sample(f, it, iz, iy + 1) * sy;
  const Vec3 b = grid_sample(f, it, iz + 1, iy) * (1.0 - sy) + grid_sample(f, it, iz + 1, iy + 1) * sy;
  return a * (1.0 - sz) + b * sz;
}

// Cell index and fraction on an axis of n nodes from 0 with spacing d; q in [0, (n−1) d].
void cell(double q, double d, int n, int& index, double& fraction) {
  const double s = q / d;
  index = static_cast<int>(std::floor(s));
  if (index >= n - 1) index = n - 2;
  if (index < 0) index = 0;
  fraction = s - index;
}

}  // namespace

void validate(const FullField& f) {
  if (f.ny < 2) bad_field("ny", "full field needs ny >= 2, got " + std::to_string(f.ny));
  if (f.nz < 2) bad_field("nz", "full field needs nz >= 2, got " + std::to_string(f.nz));
  if (f.nt < 2) bad_field("nt", "full field needs nt >= 2 time samples, got " + std::to_string(f.nt));
  if (f.n_tower < 0) bad_field("n_tower", "negative number of tower points");
  if (!(f.dy_m > 0.0) || !(f.dz_m > 0.0) || !(f.dt_s > 0.0))
    bad_field("dy/dz/dt", "full-field spacings must be positive");
  if (!(f.u_hub_m_s > 0.0))
    bad_field("u_hub", "advection speed (hub mean speed) must be positive for Taylor's hypothesis");
  if (!std::isfinite(f.z_bottom_m) || !std::isfinite(f.z_hub_m)) bad_field("z_bottom", "not finite");
  if (f.nt_held < 0 || f.nt_tail < 0 || (f.nt_held == 0 && f.nt_tail > 0) ||
      (f.nt_held > 0 && (f.nt_held < 2 || f.nt_held + f.nt_tail >= f.nt || !f.periodic)))
    bad_field("nt_held", "held samples must be 0 (all), or first and last samples fewer than nt together of a periodic field, got " +
                             std::to_string(f.nt_held) + " and " + std::to_string(f.nt_tail));
  const std::size_t held = static_cast<std::size_t>(f.held_steps());
  const std::size_t expected = held * f.nz * f.ny * 3;
  if (f.grid.size() != expected)
    bad_field("grid", "grid array has " + std::to_string(f.grid.size()) + " values, expected held samples*nz*ny*3 = " +
                          std::to_string(expected));
  if (f.tower.size() != held * f.n_tower * 3)
    bad_field("tower", "tower array size differs from held samples*n_tower*3");
}

bool covers(const FullField& f, const Vec3& p) {
  const double y = p.y() + f.half_width_m();
  const double z = p.z() - f.z_bottom_m;
  constexpr double slack = 1e-9;
  if (y < -slack || y > 2.0 * f.half_width_m() + slack || z > (f.nz - 1) * f.dz_m + slack) return false;
  return z >= -slack || (f.n_tower > 0 && p.z() > 0.0);
}

Vec3 full_field_velocity(const FullField& f, const Vec3& p, double time_s) {
  const TimeBracket tb = bracket_time(f, time_s + (f.initial_x_m() - p.x()) / f.u_hub_m_s, time_s);
  const double y = p.y() + f.half_width_m();
  const double z = p.z() - f.z_bottom_m;
  constexpr double slack = 1e-9;  // [m], points on the boundary up to rounding
  if (y < -slack || y > 2.0 * f.half_width_m() + slack || z > (f.nz - 1) * f.dz_m + slack)
    outside(time_s, "point (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
                        std::to_string(p.z()) + ") m lies outside the full-field grid");
  if (z >= -slack) {
    int iy, iz;
    double sy, sz;
    cell(y, f.dy_m, f.ny, iy, sy);
    cell(z, f.dz_m, f.nz, iz, sz);
    return grid_bilinear(f, tb.lower, iy, sy, iz, sz) * (1.0 - tb.weight) +
           grid_bilinear(f, tb.upper, iy, sy, iz, sz) * tb.weight;
  }
  if (f.n_tower == 0 || p.z() <= 0.0)
    outside(time_s, "point at z = " + std::to_string(p.z()) + " m lies below the full-field grid" +
                        (f.n_tower == 0 ? " and the field has no tower points" : ""));
  // Below the grid: tower point k at depth k·dz under z_bottom; below the last one, to zero at z = 0.
  const double depth = -z / f.dz_m;
  const int k = static_cast<int>(std::floor(depth));
  auto at_time = [&](int it) -> Vec3 {
    if (k + 1 < f.n_tower) {
      const double s = depth - k;
      return tower_sample(f, it, k) * (1.0 - s) + tower_sample(f, it, k + 1) * s;
    }
    const double z_last = f.z_bottom_m - (f.n_tower - 1) * f.dz_m;
    return tower_sample(f, it, f.n_tower - 1) * (p.z() / z_last);
  };
  return at_time(tb.lower) * (1.0 - tb.weight) + at_time(tb.upper) * tb.weight;
}

}  // namespace fowtsim::wind
