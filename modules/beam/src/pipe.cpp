#include "fowtsim/beam/pipe.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "fowtsim/beam/benchmarks.hpp"
#include "fowtsim/core/error.hpp"

namespace fowtsim::beam {
namespace {

void check(bool ok, const std::string& field, const std::string& expected) {
  if (!ok) throw InputError({"pipe", std::nullopt, field, expected}, "pipe." + field + ": expected " + expected);
}

void validate(const PipeDefinition& d) {
  check(std::isfinite(d.outer_diameter_m) && d.outer_diameter_m > 0.0, "outer_diameter_m", "a positive number");
  check(std::isfinite(d.inner_diameter_m) && d.inner_diameter_m >= 0.0 && d.inner_diameter_m < d.outer_diameter_m,
        "inner_diameter_m", "0 ≤ inner diameter < outer diameter");
  check(std::isfinite(d.youngs_modulus_pa) && d.youngs_modulus_pa > 0.0, "youngs_modulus_pa", "a positive number");
  check(std::isfinite(d.poisson_ratio) && d.poisson_ratio > -1.0 && d.poisson_ratio < 0.5, "poisson_ratio",
        "−1 < ν < 0.5");
  check(std::isfinite(d.shear_coefficient) && d.shear_coefficient > 0.0, "shear_coefficient", "a positive number");
  check(std::isfinite(d.pipe_density_kg_m3) && d.pipe_density_kg_m3 > 0.0, "pipe_density_kg_m3", "a positive number");
  check(std::isfinite(d.fluid_density_kg_m3) && d.fluid_density_kg_m3 >= 0.0, "fluid_density_kg_m3",
        "a non-negative number");
  check(std::isfinite(d.flow_velocity_m_s), "flow_velocity_m_s", "a finite number");
  check(d.flow_velocity_m_s == 0.0 || (d.fluid_density_kg_m3 > 0.0 && d.inner_diameter_m > 0.0),
        "flow_velocity_m_s", "0 unless the pipe has a bore and a fluid");
  check(std::isfinite(d.fluid_viscosity_pa_s) && d.fluid_viscosity_pa_s >= 0.0, "fluid_viscosity_pa_s",
        "a non-negative number");
  check(std::isfinite(d.wall_roughness_m) && d.wall_roughness_m >= 0.0, "wall_roughness_m", "a non-negative number");
  check(std::isfinite(d.stiffness_damping_s) && d.stiffness_damping_s >= 0.0, "stiffness_damping_s",
        "a non-negative number");
  check(std::isfinite(d.boundary_pressure_pa), "boundary_pressure_pa", "a finite number");
}

double circle_area(double d) { return 0.25 * std::numbers::pi * d * d; }
double circle_second_moment(double d) { return std::numbers::pi * d * d * d * d / 64.0; }

}  // namespace

double darcy_friction_factor(double reynolds, double relative_roughness) {
  if (reynolds <= 0.0) return 0.0;
  if (reynolds < 2300.0) return 64.0 / reynolds;
  const double x = -1.8 * std::log10(std::pow(relative_roughness / 3.7, 1.11) + 6.9 / reynolds);
  return 1.0 / (x * x);
}

BeamDefinition pipe_beam_definition(const PipeDefinition& d) {
  validate(d);
  const double area = circle_area(d.outer_diameter_m) - circle_area(d.inner_diameter_m);            // A^p
  const double second = circle_second_moment(d.outer_diameter_m) - circle_second_moment(d.inner_diameter_m);  // I
  const double shear_modulus = d.youngs_modulus_pa / (2.0 * (1.0 + d.poisson_ratio));
  const double shear = d.shear_coefficient * shear_modulus * area;
  const Vec6 k = (Vec6() << shear, shear, d.youngs_modulus_pa * area, d.youngs_modulus_pa * second,
                  d.youngs_modulus_pa * second, 2.0 * shear_modulus * second)
                     .finished();
  const double fluid_second = circle_second_moment(d.inner_diameter_m);
  const double mass = d.pipe_density_kg_m3 * area + d.fluid_density_kg_m3 * circle_area(d.inner_diameter_m);
  const double bending_inertia = d.pipe_density_kg_m3 * second + d.fluid_density_kg_m3 * fluid_second;
  const Vec3 rotary(bending_inertia, bending_inertia, 2.0 * d.pipe_density_kg_m3 * second);
  BeamDefinition beam{d.line, {benchmarks::uniform_station(0.0, k, mass, rotary),
                               benchmarks::uniform_station(1.0, k, mass, rotary)}};
  beam.stiffness_damping = Vec6::Constant(d.stiffness_damping_s);
  beam.root_end = d.root_end;
  beam.tip_end = d.tip_end;
  return beam;
}

InternalFlow pipe_flow(const PipeDefinition& d) {
  validate(d);
  InternalFlow flow;
  flow.flow_area_m2 = circle_area(d.inner_diameter_m);
  flow.fluid_mass_per_length_kg_m = d.fluid_density_kg_m3 * flow.flow_area_m2;
  flow.velocity_m_s = d.flow_velocity_m_s;
  if (d.fluid_viscosity_pa_s > 0.0 && d.inner_diameter_m > 0.0) {
    const double reynolds =
        d.fluid_density_kg_m3 * std::abs(d.flow_velocity_m_s) * d.inner_diameter_m / d.fluid_viscosity_pa_s;
    const double f = darcy_friction_factor(reynolds, d.wall_roughness_m / d.inner_diameter_m);
    flow.friction_per_length_n_m =
        f * flow.fluid_mass_per_length_kg_m * d.flow_velocity_m_s * std::abs(d.flow_velocity_m_s) /
        (2.0 * d.inner_diameter_m);
  }
  flow.boundary_pressure_pa = d.boundary_pressure_pa;
  flow.pressure_at_tip = d.pressure_at_tip;
  flow.seed_momentum_flux = d.seed_momentum_flux;
  return flow;
}

BeamModel discretise_pipe(const PipeDefinition& def, int segments) {
  BeamModel model = discretise(pipe_beam_definition(def), segments);
  model.flow = pipe_flow(def);
  return model;
}

}  // namespace fowtsim::beam
