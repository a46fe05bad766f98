#include "fowtsim/hydro/oc3.hpp"

namespace fowtsim::hydro {

Params oc3_hywind_params(int strips_lower, int strips_taper, int strips_upper) {
  Params p;
  p.water_density_kg_m3 = 1025.0;
  p.gravity_m_s2 = 9.80665;
  const auto member = [](double z_a, double z_b, double d_a, double d_b, int strips) {
    MemberParams m;
    m.end_a_body_m = Vec3(0.0, 0.0, z_a);
    m.end_b_body_m = Vec3(0.0, 0.0, z_b);
    m.diameter_a_m = d_a;
    m.diameter_b_m = d_b;
    m.cd = 0.6;
    m.ca = 1.0;
    m.strips = strips;
    return m;
  };
  p.members = {member(-120.0, -12.0, 9.4, 9.4, strips_lower), member(-12.0, -4.0, 9.4, 6.5, strips_taper),
               member(-4.0, 10.0, 6.5, 6.5, strips_upper)};
  p.added_stiffness(5, 5) = 98340000.0;
  p.added_damping.diagonal() << 100000.0, 100000.0, 130000.0, 0.0, 0.0, 13000000.0;
  return p;
}

}  // namespace fowtsim::hydro
