// Tests of the BeamDyn stand-alone input reader: the reference cases in ../shared/reference (r-test
// and our OpenFAST runs) and small synthetic files for layouts and errors the references lack.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/io/beamdyn_input.hpp"
#include "fowtsim/testing/skip.hpp"

namespace {

namespace fs = std::filesystem;
using fowtsim::io::BeamDynCase;
using fowtsim::io::read_beamdyn_driver;

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::string with_crlf(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

// 1-based number of the first line of `text` containing `needle` (0 if none).
int line_of(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  if (pos == std::string::npos) return 0;
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  REQUIRE(pos != std::string::npos);
  return text.replace(pos, from.size(), to);
}

// Every bd_driver.inp of the reference cases, keyed by a short case name.
std::map<std::string, fs::path> reference_drivers() {
  const auto reference = fowtsim::testing::shared_dir_or_skip() / "reference";
  std::map<std::string, fs::path> drivers;
  const auto add_cases_under = [&](const fs::path& dir, const std::string& prefix) {
    if (!fs::is_directory(dir)) return;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (fs::is_regular_file(entry.path() / "bd_driver.inp")) {
        drivers[prefix + entry.path().filename().string()] = entry.path() / "bd_driver.inp";
      }
    }
  };
  add_cases_under(reference / "r-test" / "modules" / "beamdyn", "r-test/");
  add_cases_under(reference / "openfast-runs" / "bd_driver_rtest" / "modules" / "beamdyn", "runs/");
  const auto rotating = reference / "openfast-runs" / "bd_5MW_rotating_gravity" / "bd_driver.inp";
  if (fs::is_regular_file(rotating)) drivers["runs/bd_5MW_rotating_gravity"] = rotating;
  return drivers;
}

// ---------------------------------------------------------------------------------------------
// A synthetic case in the older layouts (primary without QuasiStaticInit, load_retries,
// tngt_stf_*, RotStates and OutFmt but with the pitch actuator; blade without modal damping), with
// one point load, DEFAULTs in several spellings and D exponents.

const std::string kDriver =
    R"(------- BEAMDYN Driver with OpenFAST INPUT FILE --------------------------------
Synthetic driver
---------------------- SIMULATION CONTROL --------------------------------------
true          DynamicSolve  - Dynamic solve (false for static solve) (-)
        0.5   t_initial     - Starting time of simulation (s)
    1.5D+01   t_final       - Ending time of simulation   (s)
     1.0d-3   dt            - Time increment size         (s)
---------------------- GRAVITY PARAMETER --------------------------------------
          0   Gx            - Component of gravity vector along X direction (m/s^2)
          0   Gy            - Component of gravity vector along Y direction (m/s^2)
  -9.81E+00   Gz            - Component of gravity vector along Z direction (m/s^2)
---------------------- FRAME PARAMETER --------------------------------------
          0   GlbPos(1)     - Component of position vector of the reference blade frame along X direction (m)
          0   GlbPos(2)     - Component of position vector of the reference blade frame along Y direction (m)
        1.5   GlbPos(3)     - Component of position vector of the reference blade frame along Z direction (m)
---The following 3 by 3 matrix is the direction cosine matirx ,GlbDCM(3,3),
---relates global frame to the initial blade root frame
 0.0  1.0  0.0
-1.0  0.0  0.0
 0.0  0.0  1.0
t             GlbRotBladeT0 - Reference orientation for BeamDyn calculations is aligned with initial blade root?
---------------------- ROOT VELOCITY PARAMETER ----------------------------------
          0   RootVel(4)    - Component of angular velocity vector of the beam root about X axis (rad/s)
          0   RootVel(5)    - Component of angular velocity vector of the beam root about Y axis (rad/s)
      1.0D0   RootVel(6)    - Component of angular velocity vector of the beam root about Z axis (rad/s)
---------------------- APPLIED FORCE ----------------------------------
          1   DistrLoad(1)  - Component of distributed force vector along X direction (N/m)
          2   DistrLoad(2)  - Component of distributed force vector along Y direction (N/m)
          3   DistrLoad(3)  - Component of distributed force vector along Z direction (N/m)
          4   DistrLoad(4)  - Component of distributed moment vector along X direction (N-m/m)
          5   DistrLoad(5)  - Component of distributed moment vector along Y direction (N-m/m)
          6   DistrLoad(6)  - Component of distributed moment vector along Z direction (N-m/m)
         10   TipLoad(1)    - Component of concentrated force vector at blade tip along X direction (N)
         20   TipLoad(2)    - Component of concentrated force vector at blade tip along Y direction (N)
         30   TipLoad(3)    - Component of concentrated force vector at blade tip along Z direction (N)
         40   TipLoad(4)    - Component of concentrated moment vector at blade tip along X direction (N-m)
         50   TipLoad(5)    - Component of concentrated moment vector at blade tip along Y direction (N-m)
         60   TipLoad(6)    - Component of concentrated moment vector at blade tip along Z direction (N-m)
          1   NumPointLoads - Number of point loads along blade
Non-dim blade-span eta   Fx          Fy            Fz           Mx           My           Mz
(-)                      (N)         (N)           (N)          (N-m)        (N-m)        (N-m)
0.5, 100.0, 200.0, 300.0, 400.0, 500.0, 6.0D+02
---------------------- PRIMARY INPUT FILE --------------------------------------
"sub dir/primary.inp"    InputFile - Name of the primary BeamDyn input file
)";

const std::string kPrimary =
    R"(--------- BEAMDYN with OpenFAST INPUT FILE -------------------------------------------
Synthetic primary, older layout
---------------------- SIMULATION CONTROL --------------------------------------
False         Echo             - Echo input data to "<RootName>.ech"? (flag)
        0.9   rhoinf           - Numerical damping parameter for generalized-alpha integrator
          2   quadrature       - Quadrature method: 1=Gaussian; 2=Trapezoidal (switch)
"default"     refine           - Refinement factor for trapezoidal quadrature (-) [DEFAULT = 1]
          3   n_fact           - Factorization frequency (-) [DEFAULT = 5]
DEFAULT       DTBeam           - Time step size (s)
"DEFAULT"     NRMax            - Max number of iterations in Newton-Raphson algorithm (-) [DEFAULT = 10]
    1.0D-06   stop_tol         - Tolerance for stopping criterion (-) [DEFAULT = 1E-5]
---------------------- GEOMETRY PARAMETER --------------------------------------
          2   member_total    - Total number of members (-)
          5   kp_total        - Total number of key points (-) [must be at least 3]
     1      3                 - Member number; Number of key points in this member
     2      3                 - Member number; Number of key points in this member
   kp_xr         kp_yr         kp_zr        initial_twist
   (m)            (m)          (m)            (deg)
0.0  0.0  0.0  10.0
0.0  0.0  1.0  5.0
0.0  0.0  2.0  0.0
0.1  0.0  3.0  -5.0
0.2  0.0  4.0  -1.0D+01
---------------------- MESH PARAMETER ------------------------------------------
          4   order_elem     - Order of interpolation (basis) function (-)
---------------------- MATERIAL PARAMETER --------------------------------------
"../props.inp"    BldFile - Name of file containing properties for blade (quoted string)
---------------------- PITCH ACTUATOR PARAMETERS -------------------------------
True          UsePitchAct    - Whether a pitch actuator should be used (flag)
        200   PitchJ         - Pitch actuator inertia (kg-m^2)
      2.0E7   PitchK         - Pitch actuator stiffness (kg-m^2/s^2)
      5.0E5   PitchC         - Pitch actuator damping (kg-m^2/s)
---------------------- OUTPUTS -------------------------------------------------
False         SumPrint       - Print summary data to "<RootName>.sum" (flag)
          0   NNodeOuts      - Number of nodes to output to file [0 - 9] (-)
          1   OutNd          - Nodes whose values will be output  (-)
          OutList        - The next line(s) contains a list of output parameters.
"RootFxr, RootFyr; RootFzr"
TipTDxr   TipTDyr   - a bare name: only the first field counts, as in OpenFAST
"N1Fxl"

END of OutList section (the word "END" must appear in the first 3 columns of the last OutList line)
)";

// K(i,j) = (station+1)·(10(i+1) + (j+1))·1e3, M = K·1e-6: every entry distinct and recognisable.
double stiffness_entry(int station, int i, int j) {
  return (station + 1) * (10.0 * (i + 1) + (j + 1)) * 1e3;
}

std::string blade_text() {
  std::string text =
      R"( ------- BEAMDYN V1.00.* INDIVIDUAL BLADE INPUT FILE --------------------------
 Synthetic blade, no modal damping
------ Blade Parameters --------------------------------------------------------
2                       station_total    - Number of blade input stations (-)
1                       damp_type        - Damping type (switch) {0: none, 1: stiffness-proportional, 2: modal}
------ Stiffness-Proportional Damping [used only if damp_type=1] ---------------
   mu1        mu2        mu3        mu4        mu5        mu6
   (-)        (-)        (-)        (-)        (-)        (-)
1.0D-03    2.0D-03    3.0D-03    4.0D-03    5.0D-03    6.0D-03
------ Distributed Properties --------------------------------------------------
)";
  char number[32];
  for (int s = 0; s < 2; ++s) {
    text += s == 0 ? " 0.0\n" : "\n 1.0\n";
    for (const double scale : {1.0, 1e-6}) {
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          std::snprintf(number, sizeof number, "  %.6E", stiffness_entry(s, i, j) * scale);
          text += number;
        }
        text += '\n';
      }
      if (scale == 1.0) text += "  \n";
    }
  }
  return text;
}

// Writes the synthetic case under `dir` (driver.inp, sub dir/primary.inp, props.inp).
fs::path write_synthetic_case(const fs::path& dir, const std::string& driver,
                              const std::string& primary, const std::string& blade,
                              bool crlf = false) {
  const auto convert = [crlf](const std::string& text) { return crlf ? with_crlf(text) : text; };
  write_text(dir / "driver.inp", convert(driver));
  write_text(dir / "sub dir" / "primary.inp", convert(primary));
  write_text(dir / "props.inp", convert(blade));
  return dir / "driver.inp";
}

void check_synthetic_case(const BeamDynCase& c, const fs::path& dir) {
  const auto& d = c.driver;
  CHECK(d.title == "Synthetic driver");
  CHECK(d.dynamic_solve);
  CHECK(d.t_initial_s == 0.5);
  CHECK(d.t_final_s == 15.0);
  CHECK(d.dt_s == 1.0e-3);
  CHECK(d.gravity_m_s2 == fowtsim::Vec3(0.0, 0.0, -9.81));
  CHECK(d.glb_pos_m == fowtsim::Vec3(0.0, 0.0, 1.5));
  fowtsim::Mat3 dcm;
  dcm << 0, 1, 0, -1, 0, 0, 0, 0, 1;  // rows as written
  CHECK(d.glb_dcm == dcm);
  CHECK(d.glb_rot_blade_t0);
  CHECK(d.root_angular_velocity_rad_s == fowtsim::Vec3(0.0, 0.0, 1.0));
  CHECK(d.distributed_load == (fowtsim::Vec6() << 1, 2, 3, 4, 5, 6).finished());
  CHECK(d.tip_load == (fowtsim::Vec6() << 10, 20, 30, 40, 50, 60).finished());
  REQUIRE(d.point_loads.size() == 1);
  CHECK(d.point_loads[0].eta == 0.5);
  CHECK(d.point_loads[0].load == (fowtsim::Vec6() << 100, 200, 300, 400, 500, 600).finished());
  CHECK(d.primary_file == dir / "sub dir" / "primary.inp");

  const auto& p = c.primary;
  CHECK_FALSE(p.quasi_static_init.has_value());  // no such line in the older layout
  CHECK(p.rhoinf == 0.9);
  CHECK(p.quadrature == 2);
  CHECK_FALSE(p.refine.has_value());  // "default"
  CHECK(p.n_fact == 3);
  CHECK_FALSE(p.dt_beam_s.has_value());     // DEFAULT, unquoted
  CHECK_FALSE(p.load_retries.has_value());  // no such line
  CHECK_FALSE(p.nr_max.has_value());        // "DEFAULT"
  CHECK(p.stop_tol == 1.0e-6);
  CHECK_FALSE(p.tngt_stf_fd.has_value());
  CHECK(p.member_total == 2);
  CHECK(p.kp_total == 5);
  CHECK(p.member_kp_counts == std::vector<int>{3, 3});
  REQUIRE(p.key_points.size() == 5);
  CHECK(p.key_points[3].position_m == fowtsim::Vec3(0.1, 0.0, 3.0));
  CHECK(p.key_points[0].initial_twist_deg == 10.0);
  CHECK(p.key_points[4].initial_twist_deg == -10.0);
  CHECK(p.order_elem == 4);
  CHECK(p.blade_file == dir / "sub dir" / ".." / "props.inp");
  REQUIRE(p.pitch_actuator.has_value());
  CHECK(p.pitch_actuator->use_pitch_act);
  CHECK(p.pitch_actuator->pitch_j_kg_m2 == 200.0);
  CHECK(p.pitch_actuator->pitch_k_N_m == 2.0e7);
  CHECK(p.pitch_actuator->pitch_c_N_m_s == 5.0e5);
  CHECK_FALSE(p.out_fmt.has_value());
  CHECK(p.n_node_outs == 0);
  CHECK(p.out_nd.empty());
  CHECK(p.out_list ==
        std::vector<std::string>{"RootFxr", "RootFyr", "RootFzr", "TipTDxr", "N1Fxl"});

  const auto& b = c.blade;
  CHECK(b.station_total == 2);
  CHECK(b.damp_type == 1);
  CHECK(b.mu == (fowtsim::Vec6() << 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3).finished());
  CHECK(b.zeta.empty());
  REQUIRE(b.stations.size() == 2);
  CHECK(b.stations[0].eta == 0.0);
  CHECK(b.stations[1].eta == 1.0);
  for (int s = 0; s < 2; ++s) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        // Written with 7 significant digits (%.6E), all exact in these integers.
        CHECK(b.stations[s].stiffness(i, j) == stiffness_entry(s, i, j));
        CHECK(b.stations[s].mass(i, j) == Approx(stiffness_entry(s, i, j) * 1e-6).epsilon(1e-12));
      }
    }
  }
}

std::string error_of(const fs::path& driver) {
  try {
    read_beamdyn_driver(driver);
  } catch (const fowtsim::InputError& error) {
    return error.what();
  }
  FAIL("no InputError for " << driver);
  return {};
}

}  // namespace

TEST_CASE("BeamDyn reader: every reference driver case reads", "[verification]") {
  // Intent: the reader copes with every BeamDyn driver case we hold (r-test and our OpenFAST runs:
  // LF and CRLF files, with and without the driver's VTK section), and what it returns is
  // consistent: counts match table lengths, stations span eta 0..1, OutList is non-empty.
  const auto drivers = reference_drivers();
  REQUIRE(drivers.size() >= 8);  // 5 r-test cases, 2 re-runs, the rotating 5MW run
  for (const auto& [name, path] : drivers) {
    INFO(name);
    const BeamDynCase c = read_beamdyn_driver(path);
    CHECK(c.primary.file == c.driver.primary_file);
    CHECK(c.blade.file == c.primary.blade_file);
    CHECK(static_cast<int>(c.primary.key_points.size()) == c.primary.kp_total);
    CHECK(static_cast<int>(c.primary.member_kp_counts.size()) == c.primary.member_total);
    CHECK(static_cast<int>(c.blade.stations.size()) == c.blade.station_total);
    CHECK(c.blade.stations.front().eta == 0.0);
    CHECK(c.blade.stations.back().eta == 1.0);
    CHECK(c.blade.zeta == std::vector<double>{0.01, 0.02, 0.03, 0.04});  // all files: newer layout
    CHECK(c.primary.quasi_static_init == false);
    CHECK(c.primary.out_fmt == "ES16.8E2");
    CHECK_FALSE(c.primary.pitch_actuator.has_value());
    CHECK_FALSE(c.primary.out_list.empty());
    CHECK(c.driver.point_loads.empty());  // NumPointLoads 0 everywhere
    CHECK(c.driver.glb_dcm == fowtsim::Mat3::Identity());
  }
}

TEST_CASE("BeamDyn reader: NREL 5MW cases match their files", "[verification]") {
  // Intent: the 49-key-point, 49-station NREL 5MW blade reads with the numbers its files hold
  // (bd_primary.inp, beam_props.inp, bd_driver.inp of each case), including the edits of our
  // rotating-gravity run (README there): ω = 1.267109 rad/s about X, g = −9.80665 along Y,
  // μ = 0.003 on all six components, t_final 300 s, dt 0.005 s.
  const auto drivers = reference_drivers();
  for (const std::string name :
       {"r-test/bd_5MW_dynamic_gravity_Az00", "runs/bd_5MW_dynamic_gravity_Az00",
        "runs/bd_5MW_rotating_gravity"}) {
    INFO(name);
    REQUIRE(drivers.count(name) == 1);
    const BeamDynCase c = read_beamdyn_driver(drivers.at(name));
    CHECK(c.driver.dynamic_solve);
    CHECK(c.driver.glb_pos_m == fowtsim::Vec3(0.0, 0.0, 1.0));
    CHECK_FALSE(c.driver.glb_rot_blade_t0);
    CHECK(c.primary.title == "NREL 5MW blade primary input file");
    CHECK(c.primary.rhoinf == 0.0);
    CHECK(c.primary.quadrature == 2);
    CHECK_FALSE(c.primary.refine.has_value());
    CHECK_FALSE(c.primary.stop_tol.has_value());
    CHECK(c.primary.member_total == 1);
    CHECK(c.primary.kp_total == 49);
    CHECK(c.primary.member_kp_counts == std::vector<int>{49});
    CHECK(c.primary.key_points[0].initial_twist_deg == 13.308);
    CHECK(c.primary.key_points[1].position_m == fowtsim::Vec3(0.0, 0.0, 0.199875));
    CHECK(c.primary.key_points.back().position_m == fowtsim::Vec3(0.0, 0.0, 61.5));
    CHECK(c.primary.order_elem == 5);
    CHECK(c.primary.n_node_outs == 2);
    CHECK(c.primary.out_nd == std::vector<int>{1, 3});  // written "1,          3"
    CHECK(c.primary.out_list ==
          std::vector<std::string>{"RootFxr", "RootFyr", "RootFzr", "RootMxr", "RootMyr", "RootMzr",
                                   "N1Fxl", "N1Fyl", "N1Fzl", "N1Mxl", "N1Myl", "N1Mzl", "TipTDxr",
                                   "TipTDyr", "TipTDzr", "TipRDxr", "TipRDyr", "TipRDzr"});
    REQUIRE(c.blade.station_total == 49);
    CHECK(c.blade.stations[1].eta == 0.00325);
    const auto& root = c.blade.stations.front();
    CHECK(root.stiffness(4, 4) == 1.811000e10);  // EI flap (bending about y) at the root [N·m²]
    CHECK(root.stiffness(3, 3) == 1.811360e10);  // EI edge
    CHECK(root.stiffness(2, 2) == 9.729480e09);  // EA
    CHECK(root.mass(0, 0) == 678.935);           // mass per length [kg/m]
    CHECK(root.mass(5, 5) == 1945.9);
    const auto& tip = c.blade.stations.back();
    CHECK(tip.stiffness(4, 4) == 1.7e5);
    CHECK(tip.stiffness(5, 5) == 1.9e5);
  }
  const BeamDynCase az00 = read_beamdyn_driver(drivers.at("r-test/bd_5MW_dynamic_gravity_Az00"));
  CHECK(az00.driver.gravity_m_s2 == fowtsim::Vec3(0.0, -9.8, 0.0));
  CHECK(az00.driver.root_angular_velocity_rad_s == fowtsim::Vec3::Zero());
  CHECK(az00.driver.t_final_s == 30.0);
  CHECK(az00.driver.dt_s == 0.01);
  CHECK(az00.blade.mu == (fowtsim::Vec6() << 1e-3, 1e-3, 1e-3, 0.0014, 0.0022, 0.0022).finished());

  const BeamDynCase rotating = read_beamdyn_driver(drivers.at("runs/bd_5MW_rotating_gravity"));
  CHECK(rotating.driver.root_angular_velocity_rad_s == fowtsim::Vec3(1.267109, 0.0, 0.0));
  CHECK(rotating.driver.gravity_m_s2 == fowtsim::Vec3(0.0, -9.80665, 0.0));
  CHECK(rotating.driver.t_final_s == 300.0);
  CHECK(rotating.driver.dt_s == 0.005);
  CHECK(rotating.blade.mu == fowtsim::Vec6::Constant(3e-3));
}

TEST_CASE("BeamDyn reader: r-test static cases match their files", "[verification]") {
  // Intent: the small r-test cases read with their loads, geometry and sections as written:
  // curved beam (tip Fy 600 N, 45° arc key points), isotropic roll-up (tip Mx −12.5664 N·m, CRLF),
  // static cantilever (Gx 9.806, CRLF, driver with the VTK section), twisted beam (11 key points
  // twisting to 90°, tip Fy −4 MN, tngt_stf_fd written False rather than DEFAULT).
  const auto drivers = reference_drivers();

  const BeamDynCase curved = read_beamdyn_driver(drivers.at("r-test/bd_curved_beam"));
  CHECK_FALSE(curved.driver.dynamic_solve);
  CHECK(curved.driver.tip_load == (fowtsim::Vec6() << 0, 600, 0, 0, 0, 0).finished());
  CHECK(curved.primary.kp_total == 3);
  CHECK(curved.primary.key_points[1].position_m == fowtsim::Vec3(7.61205, 0.0, 38.2683));
  CHECK(curved.primary.key_points[2].position_m == fowtsim::Vec3(29.2893, 0.0, 70.7107));
  CHECK(curved.primary.order_elem == 10);
  CHECK(curved.primary.quadrature == 1);
  CHECK(curved.primary.refine == 1);
  CHECK(curved.primary.out_nd == std::vector<int>{9});
  CHECK(curved.primary.out_list ==
        std::vector<std::string>{"RootFxr", "RootFyr", "RootFzr", "RootMxr", "RootMyr", "RootMzr",
                                 "TipTDxr", "TipTDyr", "TipTDzr", "TipRDxr", "TipRDyr", "TipRDzr"});
  CHECK(curved.blade.station_total == 2);
  CHECK(curved.blade.stations[0].stiffness(0, 0) == 41.6667e5);  // written "41.6667E+5"
  CHECK(curved.blade.stations[0].stiffness(2, 2) == 100.0e5);    // written "100.E+5"
  CHECK(curved.blade.stations[1].stiffness(4, 4) == 8.333e5);

  const BeamDynCase rollup = read_beamdyn_driver(drivers.at("r-test/bd_isotropic_rollup"));
  CHECK(rollup.driver.tip_load == (fowtsim::Vec6() << 0, 0, 0, -12.5664, 0, 0).finished());
  CHECK(rollup.primary.order_elem == 15);
  CHECK(rollup.primary.title == "Isotropic beam");
  CHECK(rollup.blade.stations[0].stiffness(5, 5) == 200.0);
  CHECK(rollup.blade.stations[1].mass(5, 5) == 2.0);
  CHECK(rollup.primary.out_list ==
        std::vector<std::string>{"TipTDxr", "TipTDyr", "TipTDzr", "TipRDxr", "TipRDyr", "TipRDzr"});

  const BeamDynCase cantilever =
      read_beamdyn_driver(drivers.at("r-test/bd_static_cantilever_beam"));
  CHECK(cantilever.driver.gravity_m_s2 == fowtsim::Vec3(9.806, 0.0, 0.0));
  CHECK(cantilever.driver.title == "Static analysis of a twisted beam");  // sic, in the r-test file
  CHECK(cantilever.primary.key_points[2].position_m == fowtsim::Vec3(0.0, 0.0, 10.0));

  const BeamDynCase twisted = read_beamdyn_driver(drivers.at("r-test/bd_static_twisted_with_k1"));
  CHECK(twisted.driver.tip_load(1) == -4.0e6);
  CHECK(twisted.driver.glb_pos_m == fowtsim::Vec3(0.0, 0.0, 1.0));
  CHECK(twisted.primary.kp_total == 11);
  CHECK(twisted.primary.key_points[5].initial_twist_deg == 45.0);
  CHECK(twisted.primary.key_points.back().initial_twist_deg == 90.0);
  CHECK(twisted.primary.refine == 20);
  CHECK(twisted.primary.tngt_stf_fd == false);
  CHECK(twisted.primary.tngt_stf_comp == false);
  CHECK_FALSE(twisted.primary.tngt_stf_pert.has_value());
  CHECK(twisted.blade.stations[0].stiffness(3, 3) == 0.520833e9);     // EI_1
  CHECK(twisted.blade.stations[0].stiffness(5, 5) == 0.141872656e9);  // GJ
}

TEST_CASE("BeamDyn reader: older layouts, DEFAULTs, D exponents and CRLF", "[unit]") {
  // Intent: a case in the older layouts (no QuasiStaticInit, load_retries, tngt_stf_*, OutFmt or
  // modal damping; a pitch-actuator section; NNodeOuts 0 with a placeholder OutNd) reads by name,
  // with DEFAULT quoted, unquoted and lower-case, D exponents, a comma-separated point-load row,
  // several channels per OutList line, a quoted path with a blank, and paths relative to each
  // referencing file. The same files with CRLF line ends read the same.
  const auto dir = fowtsim::testing::scratch_dir("beamdyn_synthetic");
  const auto driver = write_synthetic_case(dir / "lf", kDriver, kPrimary, blade_text());
  check_synthetic_case(read_beamdyn_driver(driver), dir / "lf");
  const auto crlf_driver =
      write_synthetic_case(dir / "crlf", kDriver, kPrimary, blade_text(), true);
  check_synthetic_case(read_beamdyn_driver(crlf_driver), dir / "crlf");

  // Without NumPointLoads (older drivers), the primary-file line follows TipLoad(6) directly.
  std::string no_point_loads = kDriver;
  const auto first = no_point_loads.find("          1   NumPointLoads");
  no_point_loads.erase(first, no_point_loads.find("---------------------- PRIMARY") - first);
  const auto old_driver = write_synthetic_case(dir / "old", no_point_loads, kPrimary, blade_text());
  CHECK(read_beamdyn_driver(old_driver).driver.point_loads.empty());
}

TEST_CASE("BeamDyn reader: bad values name the file, line and key", "[unit]") {
  // Intent: every rejected value is an InputError "file:line: key: expected …, got "…"", so the
  // user can go straight to it; the primary and blade files are named, not only the driver.
  const auto dir = fowtsim::testing::scratch_dir("beamdyn_errors");
  const std::string blade = blade_text();
  const auto error_with_primary = [&](const std::string& name, const std::string& primary) {
    return error_of(write_synthetic_case(dir / name, kDriver, primary, blade));
  };

  const std::string bad_kp_total =
      replaced(kPrimary, "          5   kp_total", "        abc   kp_total");
  CHECK_THAT(error_with_primary("kp_total", bad_kp_total),
             Catch::Contains("primary.inp:" + std::to_string(line_of(kPrimary, "kp_total")) +
                             ": kp_total: expected an integer ≥ 3, got \"abc\""));

  const std::string bad_row = replaced(kPrimary, "0.0  0.0  1.0  5.0", "0.0  0.0  1.O  5.0");
  CHECK_THAT(
      error_with_primary("key_point", bad_row),
      Catch::Contains("primary.inp:" + std::to_string(line_of(kPrimary, "0.0  0.0  1.0  5.0")) +
                      ": key point 2") &&
          Catch::Contains("expected a number, got \"1.O\""));

  const std::string bad_flag =
      replaced(kPrimary, "True          UsePitchAct", "Maybe         UsePitchAct");
  CHECK_THAT(error_with_primary("flag", bad_flag),
             Catch::Contains("primary.inp:" + std::to_string(line_of(kPrimary, "UsePitchAct")) +
                             ": UsePitchAct: expected True or False"));

  const std::string bad_members = replaced(kPrimary, "     2      3    ", "     2      4    ");
  CHECK_THAT(error_with_primary("members", bad_members),
             Catch::Contains("kp_total + member_total − 1 = 6") && Catch::Contains("got 7"));

  const std::string no_end = kPrimary.substr(0, kPrimary.find("END of OutList"));
  CHECK_THAT(error_with_primary("no_end", no_end),
             Catch::Contains("OutList: expected a line starting with END after the channel names"));

  const std::string no_t_final = replaced(kDriver, "    1.5D+01   t_final", "    1.5D+01   t_end");
  CHECK_THAT(error_of(write_synthetic_case(dir / "t_final", no_t_final, kPrimary, blade)),
             Catch::Contains("driver.inp: t_final: expected a line"));

  const std::string bad_eta = replaced(blade, "\n 1.0\n", "\n 0.0\n");
  CHECK_THAT(error_of(write_synthetic_case(dir / "eta", kDriver, kPrimary, bad_eta)),
             Catch::Contains("props.inp:" + std::to_string(line_of(blade, "\n 1.0\n") + 1) +
                             ": station 2 eta: expected more than station 1's eta 0, got \"0.0\""));

  const std::string short_row = blade.substr(0, blade.rfind('\n', blade.size() - 2) + 1);
  CHECK_THAT(
      error_of(write_synthetic_case(dir / "short", kDriver, kPrimary, short_row)),
      Catch::Contains("station 2 mass row 6: expected 6 numbers, reached the end of the file"));
}

TEST_CASE("BeamDyn reader: a missing file is reported where it is named", "[unit]") {
  // Intent: a primary or blade file that does not exist is an InputError at the line of the file
  // that names it, with the name as written and the path looked for; a missing driver names itself.
  const auto dir = fowtsim::testing::scratch_dir("beamdyn_missing");
  const std::string driver =
      replaced(kDriver, "\"sub dir/primary.inp\"", "\"nowhere/primary.inp\"");
  CHECK_THAT(error_of(write_synthetic_case(dir / "primary", driver, kPrimary, blade_text())),
             Catch::Contains("driver.inp:" + std::to_string(line_of(kDriver, "InputFile")) +
                             ": InputFile: file \"nowhere/primary.inp\" not found"));

  const std::string primary = replaced(kPrimary, "\"../props.inp\"", "\"../blade.inp\"");
  CHECK_THAT(error_of(write_synthetic_case(dir / "blade", kDriver, primary, blade_text())),
             Catch::Contains("primary.inp:" + std::to_string(line_of(kPrimary, "BldFile")) +
                             ": BldFile: file \"../blade.inp\" not found"));

  CHECK_THAT(error_of(dir / "absent.inp"), Catch::Contains("absent.inp"));
}

TEST_CASE("BeamDyn reader: a blade file cut short or with more stations than declared is refused", "[unit]") {
  // Intent: the stations table is checked for completeness. A file cut inside its last number
  // ("1.500000E-05" cut to "1.50") still parses; only the missing line end tells, so a last line
  // without one is refused at that line. Rows after the declared station_total stations mean the
  // count and the table disagree.
  const auto dir = fowtsim::testing::scratch_dir("beamdyn_truncated");
  const std::string blade = blade_text();
  const std::string cut = blade.substr(0, blade.size() - 9);
  CHECK_THAT(error_of(write_synthetic_case(dir / "cut", kDriver, kPrimary, cut)),
             Catch::Contains("props.inp:" + std::to_string(std::count(blade.begin(), blade.end(), '\n')) +
                             ": station 2 mass row 6: the file ends inside this line, without a line end"));
  // The same without its final line end only: still refused (the last number could be cut).
  CHECK_THAT(error_of(write_synthetic_case(dir / "no_line_end", kDriver, kPrimary, blade.substr(0, blade.size() - 1))),
             Catch::Contains("station 2 mass row 6: the file ends inside this line"));
  const std::string one_station = replaced(blade, "2                       station_total", "1                       station_total");
  CHECK_THAT(error_of(write_synthetic_case(dir / "extra", kDriver, kPrimary, one_station)),
             Catch::Contains("props.inp:" + std::to_string(line_of(blade, "\n 1.0\n") + 1) +
                             ": station_total: expected the end of the file after station 1 (station_total), found more rows"));
}

TEST_CASE("BeamDyn reader: a directory named where a file belongs is called a directory", "[unit]") {
  const auto dir = fowtsim::testing::scratch_dir("beamdyn_directory");
  const auto driver = write_synthetic_case(dir, kDriver, kPrimary, blade_text());
  fs::remove(dir / "props.inp");
  fs::create_directories(dir / "props.inp");
  CHECK_THAT(error_of(driver), Catch::Contains("BldFile: file \"../props.inp\" is a directory, not a file"));
}
