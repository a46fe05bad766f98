#pragma once
// The deterministic IEC 61400-1 wind events, superposed on whatever wind the deck's model gives.
// Subclauses of ed. 3 (2005) / ed. 4 (2019), which keeps these formulas unchanged; equation numbers
// only where we could check them (ed. 3: eq. 11 NTM σ1, eqs. 26–27 EWS).
// τ = t − start_s; before τ = 0 an event adds nothing; V_hub = wind.speed_m_s, z_hub =
// wind.reference_height_m, σ1 = NTM σ1 at V_hub (eq. 11), Λ1 (eq. 5), D the rotor diameter, s = ±1:
//   EOG (§6.3.2.2 / §6.3.3.3), T = 10.5 s: ΔV = −0.37 V_gust sin(3πτ/T)(1 − cos(2πτ/T)) for 0 ≤ τ ≤ T,
//        V_gust = min(1.35 (V_e1 − V_hub), 3.3 σ1 / (1 + 0.1 D/Λ1)), V_e1 = 0.8 · 1.4 V_ref;
//   EDC (§6.3.2.4 / §6.3.3.5), T = 6 s: θ = 0.5 θ_e (1 − cos(πτ/T)), θ_e held after T,
//        θ_e = s · 4 arctan(σ1 / (V_hub (1 + 0.1 D/Λ1))), |θ_e| <= 180°;
//   ECD (§6.3.2.5 / §6.3.3.6), T = 10 s, V_cg = 15 m/s: ΔV = 0.5 V_cg (1 − cos(πτ/T)), θ = 0.5 θ_cg (1 − cos(πτ/T)),
//        both held after T, θ_cg = s · 180° (V_hub < 4 m/s) or s · 720°/V_hub (4 m/s <= V_hub <= V_ref);
//   EWS (§6.3.2.6 / §6.3.3.7, eqs. 26–27), T = 12 s, β = 6.4: ΔV = s (ζ/D)(2.5 + 0.2 β σ1 (D/Λ1)^¼)(1 − cos(2πτ/T)) for
//        0 ≤ τ ≤ T, ζ = z − z_hub (vertical) or y (horizontal, wind-frame lateral coordinate).
// ΔV adds to the horizontal speed along the wind; θ turns the whole inflow about the vertical through
// (0, 0, z_hub), in the sense of wind.direction_deg (+ turns +x towards −y), on top of it.
#include "fowtsim/wind/params.hpp"

namespace fowtsim::wind {

struct WindEvent {
  WindEventType type = WindEventType::none;
  double start_s = 0.0;            // event origin [s]
  double duration_s = 0.0;         // T [s]
  double gust_m_s = 0.0;           // EOG: V_gust; ECD: V_cg [m/s]
  double direction_change_rad = 0.0;  // EDC: θ_e; ECD: θ_cg, with the sign s [rad]
  double shear_m_s = 0.0;          // EWS: s (2.5 + 0.2 β σ1 (D/Λ1)^¼) [m/s] per unit ζ/D
  double rotor_diameter_m = 0.0;   // D [m]
};

// The event's amplitudes from the deck (params.event, speed_m_s, reference_height_m). Throws
// InputError for missing/invalid inputs (validate(WindParams) runs the same checks).
WindEvent make_wind_event(const WindParams& params);

// The event at time t: ΔV = speed_m_s + vertical_shear_per_s (z − z_hub) + horizontal_shear_per_s y
// (wind frame) and the turn direction_rad.
struct WindEventValue {
  double speed_m_s = 0.0;
  double vertical_shear_per_s = 0.0;
  double horizontal_shear_per_s = 0.0;
  double direction_rad = 0.0;
};
WindEventValue wind_event_at(const WindEvent& event, double time_s);

// The amplitudes on their own [m/s, rad], for the sweep and the checks (inputs as above).
double eog_gust_speed(double v_hub_m_s, double rotor_diameter_m, double hub_height_m, int iec_wind_class,
                      TurbulenceCategory category);
double edc_direction_change(double v_hub_m_s, double rotor_diameter_m, double hub_height_m, TurbulenceCategory category);
double ecd_direction_change(double v_hub_m_s);
double ews_shear_speed(double v_hub_m_s, double rotor_diameter_m, double hub_height_m, TurbulenceCategory category);

}  // namespace fowtsim::wind
