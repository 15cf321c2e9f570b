// Ship domains: the area round a ship that others should keep out of.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "asv_core/common/geometry.h"
#include "asv_core/common/types.h"

namespace asv {

// Circle domain of radius r [m] round a ship.
struct CircleDomain {
  double radius = 926.0;  // [m] default 0.5 nm
  bool contains(const Eigen::Vector2d& centre, const Eigen::Vector2d& p) const {
    return (p - centre).squaredNorm() <= radius * radius;
  }
};

// Hexagon domain of Lazarowska (2015), section 3: a to the bow, b "of amidships", c to starboard,
// d to the stern, e to port, oriented by the target's course. The paper gives the five distances but
// not the vertex layout (its figure is lost); we place, in the target's frame (forward, starboard):
//   bow (a, 0), starboard shoulder (b, c), starboard beam (0, c), stern (-d, 0), port beam (0, -e),
//   port shoulder (b, -e)
// i.e. b is how far ahead of amidships the domain keeps its full width. With the paper's values the
// hexagon is convex, 1.25 nm long and 0.85 nm wide, larger ahead and to starboard as the COLREGs want.
struct HexagonDomainConfig {
  double a = 1852.0;      // [m] towards the bow (paper: 1 nm)
  double b = 1111.2;      // [m] forward extent of the full width (paper: 0.6 nm)
  double c = 1111.2;      // [m] towards starboard (paper: 0.6 nm)
  double d = 463.0;       // [m] towards the stern (paper: 0.25 nm)
  double e = 463.0;       // [m] towards port (paper: 0.25 nm)
  void validate() const;  // all finite and positive, b < a
};

class HexagonDomain {
public:
  explicit HexagonDomain(const HexagonDomainConfig& cfg = {});
  // Polygon of the domain round a ship at `centre` heading `course` (nautical, rad), ENU.
  Polygon polygon(const Eigen::Vector2d& centre, double course) const;
  // True when p lies inside (or on) the domain.
  bool contains(const Eigen::Vector2d& centre, double course, const Eigen::Vector2d& p) const;
  const HexagonDomainConfig& config() const { return cfg_; }

private:
  HexagonDomainConfig cfg_;
  Eigen::Matrix<double, 2, 6> local_;  // (forward, starboard) vertices
};

// The ship domain of Kijima and Nakiri (2003) for restricted waters, from the ship's length L and speed
// V alone (through her advance and tactical diameter, estimated from V): with V in knots,
//   k_AD = A_D / L = 10^(0.3591 log10 V + 0.0952),   k_DT = D_T / L = 10^(0.5441 log10 V - 0.0795),
//   fore = (1 + 1.34 sqrt(k_AD^2 + (k_DT / 2)^2)) L,   aft = (1 + 0.67 sqrt(k_AD^2 + (k_DT / 2)^2)) L,
//   starboard = (0.2 + k_DT) L,                          port = (0.2 + 0.75 k_DT) L.
// A 94 m ferry at 10 kn: fore 497 m, aft 295 m, starboard 293 m, port 224 m; a 20 m launch at 8 kn:
// 98, 59, 56 and 43 m. Speeds under 1 kn count as 1 kn (the fits are for ships under way).
struct KijimaDomain {
  double fore = 0.0, aft = 0.0, starboard = 0.0, port = 0.0;  // [m]
};
KijimaDomain kijimaDomain(double length_m, double speed_mps);

// Wu et al. (2022) ship domain Dm [nm] as a function of the direction q of the CPA relative to the
// own heading, eq. (9) (the revised, continuous-ish form of eq. 8). q in degrees, any value (wrapped).
double wuDomainNm(double q_deg);
// The unrevised step form, eq. (8), kept for comparison.
double wuDomainStepNm(double theta_deg);
// Minimum safety field value rho(theta) [nm], eq. (12), theta = relative bearing of the target [deg].
double wuRhoNm(double theta_deg);

// Safe encounter distances d1, d2 of Wu et al. eq. (10)-(12) with the manoeuvring margin Td.
struct SafeEncounterConfig {
  double domain_unit_m = 1852.0;  // [m] length of the paper's "n mile" in rho and Dm; 1852 for sea-going
                                  // ships, smaller to scale the domain to a small craft
  double turn90_time_s = 60.0;    // [s] t: time for the own ship to turn 90 deg at full rudder and speed
  double advance_m = 450.0;       // [m] Ad: the own ship's advance (turning pitch) in that turn
  void validate() const;
};
struct SafeEncounter {
  double rho_m = 0.0;  // [m] rho(theta), eq. (12)
  double d1_m = 0.0;   // [m] d1 = 1.5 rho(theta), eq. (10)
  double d2_m = 0.0;   // [m] d2 = d1 + Td, eq. (11), Td = V_T t + Ad
  double td_m = 0.0;   // [m] manoeuvring margin Td
};
// theta: relative bearing of the target from the own heading [rad]; target_speed V_T [m/s].
SafeEncounter wuSafeEncounter(double theta, double target_speed, const SafeEncounterConfig& cfg);

}  // namespace asv
