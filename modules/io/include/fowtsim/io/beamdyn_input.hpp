#pragma once
// Reader of OpenFAST BeamDyn stand-alone cases: the driver input file, the primary input file it
// names and the blade-property file the primary names (BeamDyn's BD_ReadDvrFile,
// BD_ReadPrimaryFile and BD_ReadBladeFile). Values are kept as written (units as in the files,
// SI); a DEFAULT that BeamDyn would fill in stays an empty std::optional.
//
// Lines "value  Name  - description" are found by their Name, so lines that only some BeamDyn
// versions write (QuasiStaticInit, load_retries, tngt_stf_*, RotStates, the pitch actuator, OutFmt,
// the driver's NumPointLoads, the blade's modal damping) may be present or not. Tables without
// names (GlbDCM, point loads, member and key-point rows, damping coefficients, stations) are read
// after the named line they follow. Every failure is a fowtsim::InputError whose message starts
// "file:line: Name:" (or "file: Name:" for a missing line).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fowtsim/core/types.hpp"

namespace fowtsim::io {

// One row of the driver's point-load table.
struct BeamDynPointLoad {
  double eta = 0.0;          // position along the blade, fraction of its length [-]
  Vec6 load = Vec6::Zero();  // Fx, Fy, Fz [N], Mx, My, Mz [N·m]
};

// The driver input file (bd_driver.inp).
struct BeamDynDriver {
  std::filesystem::path file;        // this file, as opened
  std::string title;                 // line 2, trimmed
  bool dynamic_solve = false;        // DynamicSolve: time integration (true) or a static solve
  double t_initial_s = 0.0;          // t_initial [s] (dynamic solve only)
  double t_final_s = 0.0;            // t_final [s] (dynamic solve only)
  double dt_s = 0.0;                 // dt [s] (dynamic solve only)
  Vec3 gravity_m_s2 = Vec3::Zero();  // Gx, Gy, Gz [m/s²], global frame
  Vec3 glb_pos_m = Vec3::Zero();     // GlbPos(1..3) [m]: blade root position in the global frame
  Mat3 glb_dcm = Mat3::Identity();  // GlbDCM [-], row i of the file is row i of the matrix (BeamDyn
                                    // reads it as RootOri(i,:), the initial root orientation)
  bool glb_rot_blade_t0 = false;    // GlbRotBladeT0: BeamDyn's reference frame is the initial root
                                    // frame (true) or the global frame (false)
  Vec3 root_angular_velocity_rad_s = Vec3::Zero();  // RootVel(4..6) [rad/s] about global X, Y, Z;
                                                    // BeamDyn sets the root's linear velocity to
                                                    // ω × GlbPos itself
  Vec6 distributed_load = Vec6::Zero();  // DistrLoad(1..6): force [N/m] along X, Y, Z, then moment
                                         // [N·m/m] about X, Y, Z
  Vec6 tip_load = Vec6::Zero();          // TipLoad(1..6): force [N], then moment [N·m]
  std::vector<BeamDynPointLoad> point_loads;  // NumPointLoads rows; empty if 0 or if the file has
                                              // no NumPointLoads line (older drivers)
  std::filesystem::path primary_file;         // InputFile, resolved against this file's directory
};

// One key point of the blade reference line.
struct BeamDynKeyPoint {
  Vec3 position_m = Vec3::Zero();  // kp_xr, kp_yr, kp_zr [m], blade frame (z along the blade)
  double initial_twist_deg = 0.0;  // initial_twist [deg] as written (BeamDyn itself negates it
                                   // on reading, BeamDyn_IO.f90)
};

// Pitch-actuator section of older primary files (removed from BeamDyn in later versions).
struct BeamDynPitchActuator {
  bool use_pitch_act = false;  // UsePitchAct
  double pitch_j_kg_m2 = 0.0;  // PitchJ [kg·m²]: actuator inertia
  double pitch_k_N_m = 0.0;    // PitchK [N·m/rad]: actuator stiffness
  double pitch_c_N_m_s = 0.0;  // PitchC [N·m·s/rad]: actuator damping
};

// The primary input file (bd_primary.inp). An empty optional means "DEFAULT" in the file or no
// such line in this file version; BeamDyn's defaults are noted per field.
struct BeamDynPrimary {
  std::filesystem::path file;              // this file, as opened
  std::string title;                       // line 2, trimmed
  std::optional<bool> quasi_static_init;   // QuasiStaticInit (no DEFAULT; absent in old files)
  double rhoinf = 0.0;                     // rhoinf [-]: spectral radius at infinite frequency of
                                           // the generalized-α integrator
  int quadrature = 1;                      // quadrature: 1 Gauss, 2 trapezoidal
  std::optional<int> refine;               // refine [-] (trapezoidal only); DEFAULT 1
  std::optional<int> n_fact;               // n_fact [-]: Jacobian factorisation interval; DEFAULT 5
  std::optional<double> dt_beam_s;         // DTBeam [s]; DEFAULT: the driver's (glue code's) dt
  std::optional<int> load_retries;         // load_retries [-]; DEFAULT 20
  std::optional<int> nr_max;               // NRMax [-]: Newton–Raphson iterations; DEFAULT 10
  std::optional<double> stop_tol;          // stop_tol [-]: N-R convergence tolerance; DEFAULT 1e-5
  std::optional<bool> tngt_stf_fd;         // tngt_stf_fd: finite-difference tangent stiffness;
                                           // DEFAULT false
  std::optional<bool> tngt_stf_comp;       // tngt_stf_comp; DEFAULT false
  std::optional<double> tngt_stf_pert;     // tngt_stf_pert [-]; DEFAULT 1e-6
  std::optional<double> tngt_stf_difftol;  // tngt_stf_difftol [-]; DEFAULT 0.1
  int member_total = 0;                    // member_total (== member_kp_counts.size())
  int kp_total = 0;                        // kp_total (== key_points.size())
  std::vector<int> member_kp_counts;       // key points of member 1, 2, …; consecutive members
                                           // share an end point, so the sum is
                                           // kp_total + member_total − 1
  std::vector<BeamDynKeyPoint> key_points;  // root first
  int order_elem = 0;                       // order_elem: order of the element shape functions
  std::filesystem::path blade_file;         // BldFile, resolved against this file's directory
  std::optional<BeamDynPitchActuator> pitch_actuator;  // only in files with UsePitchAct
  std::optional<std::string> out_fmt;  // OutFmt, e.g. "ES16.8E2" (absent in old files)
  std::optional<int> n_node_outs;      // NNodeOuts [0–9]
  std::vector<int> out_nd;             // OutNd: the NNodeOuts node numbers (1-based)
  std::vector<std::string> out_list;   // OutList channel names in order, e.g. "TipTDxr"
};

// One cross-section station of the blade-property file. BeamDyn order of the 6 components:
// 1 shear x, 2 shear y, 3 axial (z along the blade), 4 bending about x, 5 bending about y,
// 6 torsion.
struct BeamDynStation {
  double eta = 0.0;               // station_eta [-]: position along the blade, 0 root … 1 tip
  Mat6 stiffness = Mat6::Zero();  // K: [N] in rows/cols 1–3, [N·m²] in 4–6, [N·m] coupling
  Mat6 mass = Mat6::Zero();       // M: [kg/m] in 1–3, [kg·m] in 4–6 (inertia per length),
                                  // [kg] coupling (mass per length × offset)
};

// The blade-property file (beam_props.inp).
struct BeamDynBlade {
  std::filesystem::path file;            // this file, as opened
  std::string title;                     // line 2, trimmed
  int station_total = 0;                 // station_total (== stations.size())
  int damp_type = 0;                     // damp_type: 0 none, 1 stiffness-proportional, 2 modal
  Vec6 mu = Vec6::Zero();                // mu1..mu6 [s]: stiffness-proportional damping, per
                                         // component (the file labels them (-))
  std::vector<double> zeta;              // modal damping ratios [-], mode 1 first; empty when
                                         // the file has no n_modes/zeta lines (older files)
  std::vector<BeamDynStation> stations;  // eta strictly increasing in [0, 1]
};

struct BeamDynCase {
  BeamDynDriver driver;
  BeamDynPrimary primary;
  BeamDynBlade blade;
};

// Reads the driver file, then the primary file it names (relative to the driver's directory),
// then the blade file the primary names (relative to the primary's directory). A missing
// referenced file is reported at the line of the file that names it.
BeamDynCase read_beamdyn_driver(const std::filesystem::path& bd_driver_inp);

// The primary and blade files on their own (BldFile is resolved but not read).
BeamDynPrimary read_beamdyn_primary(const std::filesystem::path& bd_primary_inp);
BeamDynBlade read_beamdyn_blade(const std::filesystem::path& blade_props_inp);

}  // namespace fowtsim::io
