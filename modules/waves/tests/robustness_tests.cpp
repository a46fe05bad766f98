// Robustness: calm seas, invalid parameters (InputError listing every problem), points above the
// surface or below the seabed, non-finite inputs — never a NaN.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "fowtsim/core/error.hpp"
#include "fowtsim/waves/precomputed_kinematics.hpp"
#include "test_waves.hpp"

using namespace waves_test;
using fowtsim::InputError;
using fowtsim::NumericalError;

namespace {
std::string message_of(const WaveParams& p) {
  try {
    WaveField field(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("Hs = 0, H = 0 and model still give a calm sea", "[unit][waves]") {
  WaveParams still;
  WaveParams zero_hs = jonswap(0.0, 10.0, 3.3, 320.0);
  WaveParams zero_h = regular(0.0, 10.0, 320.0);
  for (const WaveParams& p : {still, zero_hs, zero_h}) {
    for (Stretching s : {Stretching::none, Stretching::wheeler}) {
      WaveParams q = p;
      q.stretching = s;
      const WaveField field(q);
      CHECK(field.calm());
      const std::vector<Vec3> points{{0, 0, 0}, {0, 0, -10}, {3, 4, 2}};
      const PrecomputedKinematics pre(field, points);
      for (double t : {0.0, 17.3, 1e6}) {
        const WaveKinematics k = field.evaluate(Vec3(1, 2, -3), t);
        CHECK(k.wetted);
        CHECK(k.elevation_m == 0.0);
        CHECK(k.velocity_m_s.norm() == 0.0);
        CHECK(k.dynamic_pressure_Pa == 0.0);
        CHECK(pre.at(1, t).velocity_m_s.norm() == 0.0);
        CHECK(pre.at(1, t).wetted);
        CHECK_FALSE(pre.at(2, t).wetted);
        CHECK(field.elevation_series(0, 0).size() == field.record_samples());
      }
    }
  }
}

TEST_CASE("invalid wave parameters throw InputError naming the key", "[unit][waves]") {
  const WaveParams ok = jonswap(6.0, 10.0, 3.3, 320.0, 3600.0, 0.25);
  REQUIRE_NOTHROW(WaveField(ok));
  auto bad = ok;
  bad.depth_m = -10.0;
  CHECK_THROWS_AS(WaveField(bad), InputError);
  CHECK(message_of(bad).find("waves.depth_m") != std::string::npos);
  bad = ok;
  bad.depth_m = 0.0;
  CHECK(message_of(bad).find("waves.depth_m") != std::string::npos);
  bad = ok;
  bad.tp_s = 0.0;
  CHECK(message_of(bad).find("waves.tp_s") != std::string::npos);
  bad.tp_s = -3.0;
  CHECK(message_of(bad).find("waves.tp_s") != std::string::npos);
  bad = ok;
  bad.gamma = 0.9;
  CHECK(message_of(bad).find("waves.gamma") != std::string::npos);
  bad = ok;
  bad.hs_m = -1.0;
  CHECK(message_of(bad).find("waves.hs_m") != std::string::npos);
  bad = ok;
  bad.cutoff_high_hz = 3.0;  // Nyquist at dt 0.25 s is 2 Hz
  CHECK(message_of(bad).find("time step too coarse for the cut-off frequency") != std::string::npos);
  bad = ok;
  bad.dt_s = 6.0;  // Nyquist 1/12 Hz below the peak 1/10 Hz
  bad.duration_s = 3600.0;
  CHECK(message_of(bad).find("time step too coarse for the spectrum") != std::string::npos);
  bad = ok;
  bad.duration_s = 3600.1;
  CHECK(message_of(bad).find("whole multiple") != std::string::npos);
  bad = ok;
  bad.cutoff_low_hz = 0.5;
  bad.cutoff_high_hz = 0.4;
  CHECK(message_of(bad).find("cutoff_low_hz") != std::string::npos);
  bad = ok;
  bad.model = WaveModel::pierson_moskowitz;
  bad.gamma = 3.3;
  CHECK(message_of(bad).find("waves.gamma") != std::string::npos);
  bad = ok;
  bad.elevation_probes_m.assign(10, {0.0, 0.0});
  CHECK(message_of(bad).find("elevation_probes_m") != std::string::npos);
  auto reg = regular(2.0, 0.3, 20.0, 0.0, 0.0, 0.25);  // period below 2 dt
  CHECK(message_of(reg).find("time step too coarse for the wave") != std::string::npos);
  reg = regular(2.0, -1.0, 20.0);
  CHECK(message_of(reg).find("waves.period_s") != std::string::npos);
  // every problem at once
  bad = ok;
  bad.depth_m = -1.0;
  bad.tp_s = 0.0;
  bad.gamma = 0.5;
  const std::string all = message_of(bad);
  CHECK(all.find("3 problems") != std::string::npos);
  CHECK(all.find("waves.depth_m") != std::string::npos);
  CHECK(all.find("waves.tp_s") != std::string::npos);
  CHECK(all.find("waves.gamma") != std::string::npos);
  // deck spellings
  CHECK(parse_wave_model("pm") == WaveModel::pierson_moskowitz);
  CHECK(parse_stretching("wheeler") == Stretching::wheeler);
  CHECK_THROWS_AS(parse_wave_model("jonswapp"), InputError);
  CHECK_THROWS_AS(parse_stretching("linear"), InputError);
}

TEST_CASE("points above the surface or below the seabed never give NaN", "[unit][waves]") {
  for (double depth : {30.0, kInf}) {
    for (Stretching s : {Stretching::none, Stretching::wheeler}) {
      WaveParams p = jonswap(6.0, 10.0, 3.3, depth, 600.0, 0.25, 4);
      p.stretching = s;
      const WaveField field(p);
      for (double z : {50.0, 7.0, 0.5, 0.0, -0.5, -29.999999}) {
        for (double t : {0.0, 99.9, 333.3}) {
          const WaveKinematics k = field.evaluate(Vec3(2, 3, z), t);
          CHECK(std::isfinite(k.elevation_m));
          CHECK(k.velocity_m_s.allFinite());
          CHECK(k.acceleration_m_s2.allFinite());
          CHECK(std::isfinite(k.dynamic_pressure_Pa));
          if (!k.wetted) CHECK(k.velocity_m_s.norm() == 0.0);
        }
      }
      if (std::isfinite(depth)) {
        CHECK_THROWS_AS(field.evaluate(Vec3(0, 0, -31.0), 1.0), InputError);
        CHECK_NOTHROW(field.evaluate(Vec3(0, 0, -30.0 * (1 + 1e-12)), 1.0));  // round-off at the seabed
      } else {
        CHECK(field.evaluate(Vec3(0, 0, -1e5), 1.0).velocity_m_s.norm() == 0.0);  // e^{kz} underflow, no NaN
      }
      CHECK_THROWS_AS(field.evaluate(Vec3(0, 0, std::nan("")), 1.0), NumericalError);
      CHECK_THROWS_AS(field.evaluate(Vec3(0, 0, -1), std::nan("")), NumericalError);
    }
  }
}

TEST_CASE("a trough reaching the seabed leaves the column dry, not NaN", "[unit][waves]") {
  // 3 m amplitude in 2.5 m of water: nonsense for linear theory, but defined: at the trough
  // (t = T/2, η = −3 m) there is no water column, every point is dry.
  for (Stretching s : {Stretching::none, Stretching::wheeler}) {
    WaveParams p = regular(6.0, 12.0, 2.5, 0.0, 0.0, 0.1);
    p.stretching = s;
    const WaveField field(p);
    const std::vector<Vec3> points{{0, 0, -1.0}, {0, 0, -2.5}};
    const PrecomputedKinematics pre(field, points);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const WaveKinematics k = field.evaluate(points[i], 6.0), kp = pre.at(i, 6.0);
      CHECK(k.elevation_m == Approx(-3.0));
      CHECK(k.velocity_m_s.allFinite());
      CHECK(kp.velocity_m_s.allFinite());
      if (s == Stretching::wheeler) {
        CHECK_FALSE(k.wetted);
        CHECK_FALSE(kp.wetted);
      }
    }
  }
}
