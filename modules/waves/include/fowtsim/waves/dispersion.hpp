#pragma once
// Linear (Airy) dispersion relation ω² = g k tanh(k h), solved for the wavenumber k.

namespace fowtsim::waves {

// Wavenumber k [rad/m] ≥ 0 of a wave of angular frequency omega [rad/s] ≥ 0 in water of depth
// depth_m > 0 (+∞ = deep water, k = ω²/g), gravity g [m/s²] > 0. Exact to a few ulps (verified
// against 60-digit references to 1e-15): safeguarded Newton on x tanh x = y (x = k h,
// y = ω² h / g) from the Fenton & McKee (1990) explicit estimate x ≈ y (tanh y^{3/4})^{-2/3}
// (1.5 % worst case), inside the bracket max(y, √y) ≤ x ≤ y / tanh(max(y, √y)).
// Throws InputError for negative, NaN or infinite omega, depth ≤ 0 or g ≤ 0.
double wavenumber(double omega_rad_s, double depth_m, double gravity_m_s2);

// Deep-water limit k = ω²/g.
inline double deep_water_wavenumber(double omega_rad_s, double gravity_m_s2) {
  return omega_rad_s * omega_rad_s / gravity_m_s2;
}

}  // namespace fowtsim::waves
