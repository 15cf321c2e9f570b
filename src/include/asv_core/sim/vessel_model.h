// Vessel models for the simulator: Lazarowska's (2015) kinematic own-ship model and the 3-DOF MMG-type
// manoeuvring model of Wu et al. (2022), integrated with a fixed-step fourth-order Runge-Kutta.
//
// Frames and signs (README.md, Conventions): position in local ENU metres (x east, y north); heading
// psi nautical (clockwise from true north, rad); body axes x forward, y to starboard, z down, so sway v
// is positive to starboard and yaw rate r positive clockwise (a turn to starboard). A positive rudder
// angle is starboard helm: it turns the ship to starboard (r > 0), as in the MMG standard method.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/units.h"

namespace asv {

// State shared by all models. For the 3-DOF model the reference point is the origin of the body frame
// (midship; the centre of gravity lies x_G ahead of it).
struct VesselState {
  double x = 0.0;    // [m] ENU east
  double y = 0.0;    // [m] ENU north
  double psi = 0.0;  // [rad] heading, nautical, kept in [0, 2 pi)
  double u = 0.0;    // [m/s] surge velocity (through the water; there is no current)
  double v = 0.0;    // [m/s] sway velocity, positive to starboard
  double r = 0.0;    // [rad/s] yaw rate, positive clockwise (to starboard)

  Eigen::Vector2d position() const { return {x, y}; }
  // ENU velocity over ground: the body velocity rotated by the heading.
  Eigen::Vector2d velocity() const {
    const double s = std::sin(psi), c = std::cos(psi);
    return {u * s + v * c, u * c - v * s};
  }
  double speedOverGround() const { return std::hypot(u, v); }
  // Nautical course over ground [0, 2 pi); the heading when the ship does not move, so a ship at rest
  // reports where it points rather than north.
  double courseOverGround() const {
    if (u == 0.0 && v == 0.0)
      return wrapTwoPi(psi);
    return courseOf(velocity());
  }
  bool finite() const { return allFinite({x, y, psi, u, v, r}); }
};

// Control input. The 3-DOF model uses rudder and propeller_rps; the kinematic model (which has no
// actuators, Lazarowska's decision variable is the course) uses course and speed.
struct VesselInput {
  double rudder = 0.0;         // [rad] rudder angle, positive = starboard helm; clamped to the model's limit
  double propeller_rps = 0.0;  // [rev/s] propeller revolutions n; clamped to [0, n_max]
  double course = 0.0;         // [rad] kinematic model: commanded course, nautical
  double speed = 0.0;          // [m/s] kinematic model: commanded speed (>= 0)
};

// Weather acting on the 3-DOF model (Wu et al. 2022 eq. 19-21). Directions are where wind and waves
// come FROM, nautical, as a weather report gives them. Steady wind, regular waves.
struct Environment {
  double wind_speed = 0.0;      // [m/s] true wind speed, >= 0
  double wind_direction = 0.0;  // [rad] true wind direction (from), nautical
  double wave_height = 0.0;     // [m] regular wave height crest to trough, >= 0; amplitude xi_w = H / 2
  double wave_direction = 0.0;  // [rad] direction the waves come from, nautical
  double wave_length = 100.0;   // [m] wavelength lambda, > 0 (used only when wave_height > 0)
  void validate() const;        // throws std::invalid_argument naming the bad field
};

// Abstract vessel model: a state advanced by step(). Implementations never allocate in step().
class VesselModel {
public:
  virtual ~VesselModel() = default;

  // Advances the state by dt [s] (> 0) with the input held constant over the step.
  virtual void step(const VesselInput& input, const Environment& env, double dt) = 0;
  // True for a model steered by course/speed set-points (no autopilot needed), false for one steered
  // by rudder and propeller.
  virtual bool steersBySetPoints() const = 0;
  virtual double length() const = 0;  // [m] length used for display and safety distances
  virtual std::unique_ptr<VesselModel> clone() const = 0;

  const VesselState& state() const { return state_; }
  virtual void setState(const VesselState& s);
  double courseOverGround() const { return state_.courseOverGround(); }  // [rad] nautical
  double speedOverGround() const { return state_.speedOverGround(); }    // [m/s]

protected:
  VesselModel() = default;
  VesselState state_;
};

// ---------------------------------------------------------------------------------------------------
// Kinematic model, Lazarowska (2015) eq. (4)-(6).

struct KinematicParams {
  // [rad/s] omega: angular speed of the turn, "determined experimentally during the turning manoeuvre
  // trials" (Lazarowska 2015); the paper gives no value. 1 deg/s is a coaster-sized ship at ~10 kn
  // (turning radius V/omega ~ 300 m).
  double omega = degToRad(1.0);
  // [s] t01: time to pass the segment A0A1 before the ship starts to turn (rudder laid, turn develops).
  // Not given in the paper; 10 s is of the order of a rudder's hard-over time.
  double t01 = 10.0;
  double length = 100.0;  // [m] ship length, for display and safety distances only
  // A point that takes the commanded course and speed at once (scenario model `point`): Hirayama et al.
  // (2019) Fig. 1, where a ship "moves" each time step along her chosen course with no turning delay.
  // omega and t01 are then unused.
  bool instant = false;
  void validate() const;
};

// Lazarowska's own-ship model: x' = V sin psi, y' = V cos psi (eq. 4). A course change starts with a
// straight run of t01 seconds and continues as a turn at constant angular speed omega until the new
// course is reached (Fig. 4); both parts are integrated in closed form, so the position is exact for
// any dt. Speed changes are immediate (the paper keeps speed constant and models no speed manoeuvre).
// A new course command during a turn redirects the turn without a second delay.
class KinematicModel : public VesselModel {
public:
  explicit KinematicModel(const KinematicParams& p = {});
  void step(const VesselInput& input, const Environment& env, double dt) override;
  bool steersBySetPoints() const override { return true; }
  double length() const override { return p_.length; }
  std::unique_ptr<VesselModel> clone() const override { return std::make_unique<KinematicModel>(*this); }
  void setState(const VesselState& s) override;
  const KinematicParams& params() const { return p_; }

  // Manoeuvre time t_m of eq. (6) for a course alteration dpsi [rad] (sign ignored): the time of passage
  // of the line segment A0B that replaces the curve in the line-segment approximation.
  double manoeuvreTime(double dpsi) const;
  // Time from the command to reaching the new course on the real curve: t01 + |dpsi| / omega.
  double turnCompletionTime(double dpsi) const { return p_.t01 + std::abs(dpsi) / p_.omega; }

private:
  KinematicParams p_;
  double target_course_ = 0.0;  // [rad] last commanded course
  double delay_left_ = 0.0;     // [s] remaining straight run before the turn starts
  bool manoeuvring_ = false;    // delay or turn in progress
};

// ---------------------------------------------------------------------------------------------------
// 3-DOF MMG-type model, Wu et al. (2022) eq. (13)-(22).
//
// Hull coefficients are the non-dimensional ("prime") hydrodynamic derivatives of the MMG standard
// method (Yasukawa & Yoshimura 2015): forces scale with 1/2 rho L d U^2, moments with
// 1/2 rho L^2 d U^2, masses with 1/2 rho L^2 d, inertia with 1/2 rho L^4 d, v' = v / U, r' = r L / U.
// Names follow Fossen (Xvv, Yv, Nr, ...) and stand for the primes (Yv = Y'_v). Wu's eq. (14) is the
// subset R0, Xvv, Xvr, Xrr, Yv, Yr, Nv, Nr; the higher-order MMG terms (Xvvvv, Yvvv, ... Nrrr) are an
// extension that reproduces eq. (14) exactly when left at zero.
struct Mmg3DofParams {
  std::string name;         // preset name
  std::string description;  // one line, free text

  // Environment constants.
  double rho = 1025.0;     // [kg/m^3] sea water density
  double rho_air = 1.225;  // [kg/m^3] air density (ISA sea level)
  double g = 9.81;         // [m/s^2] gravitational acceleration

  // Principal particulars.
  double L = 0.0;     // [m] length between perpendiculars (eq. 20-21 use it as the waterline length)
  double B = 0.0;     // [m] breadth
  double d = 0.0;     // [m] draught
  double mass = 0.0;  // [kg] displacement mass m
  double xG = 0.0;    // [m] longitudinal centre of gravity ahead of midship (0 reproduces eq. 13)
  double kzz = 0.0;   // [m] yaw radius of gyration about the centre of gravity, I_zz = m kzz^2

  // Added masses (MMG primes): m_x, m_y, J_zz of eq. (13).
  double mx = 0.0;  // [-] m'_x
  double my = 0.0;  // [-] m'_y
  double Jz = 0.0;  // [-] J'_z

  // Hull forces, eq. (14) (primes). X(u) = -1/2 rho L d R0 u|u|.
  double R0 = 0.0;  // [-] straight-running resistance coefficient R'_0
  double Xvv = 0.0, Xvr = 0.0, Xrr = 0.0, Xvvvv = 0.0;
  double Yv = 0.0, Yr = 0.0, Yvvv = 0.0, Yvvr = 0.0, Yvrr = 0.0, Yrrr = 0.0;
  double Nv = 0.0, Nr = 0.0, Nvvv = 0.0, Nvvr = 0.0, Nvrr = 0.0, Nrrr = 0.0;

  // Propeller, eq. (15)-(16).
  double Dp = 0.0;         // [m] propeller diameter D_P
  double xP = -0.5;        // [-] x'_P: longitudinal position of the propeller / L
  double tP = 0.0;         // [-] thrust deduction factor t_P (eq. 16: 0.50 C_p - 0.12)
  double wP0 = 0.0;        // [-] wake fraction in straight running w_P0 (eq. 16: 0.7 C_p - 0.18)
  double wP_beta = 4.0;    // [-] c in w_P = w_P0 exp(-c beta_P^2); eq. (16) prints 0.4, Kijima et al. use 4.0
  double kt0 = 0.0;        // [-] a_0 of K_T(J) = a_0 + a_1 J + a_2 J^2
  double kt1 = 0.0;        // [-] a_1
  double kt2 = 0.0;        // [-] a_2
  double n_max = 0.0;      // [rev/s] highest propeller revolutions accepted (input is clamped)
  double n_nominal = 0.0;  // [rev/s] nominal (service) revolutions, documented with the steady speed

  // Rudder, eq. (17)-(18), with the MMG standard's inflow model for U_R and alpha_R.
  double AR = 0.0;          // [m^2] rudder area (A_d in eq. 18)
  double lambda_R = 0.0;    // [-] rudder aspect ratio (lambda in eq. 18)
  double HR = 0.0;          // [m] rudder span; eta = D_P / H_R
  double xR = -0.5;         // [-] x'_R: longitudinal position of the rudder / L
  double tR = 0.0;          // [-] steering resistance deduction t_R
  double aH = 0.0;          // [-] rudder force increase factor a_H
  double epsilon = 1.0;     // [-] epsilon = (1 - w_R) / (1 - w_P)
  double kappa = 0.5;       // [-] kappa: propeller slipstream factor on u_R
  double lR = -1.0;         // [-] l'_R: effective longitudinal position of the rudder for beta_R
  double gammaR_pos = 0.5;  // [-] flow straightening coefficient for beta_R >= 0
  double gammaR_neg = 0.5;  // [-] flow straightening coefficient for beta_R < 0
  double delta_max = 0.0;   // [rad] rudder angle limit (full rudder)

  // Wind, eq. (19) with C_X = -cx cos(gamma), C_Y = cy sin(gamma), C_N = cn sin(2 gamma) (Fossen 2011).
  double Af = 0.0;                        // [m^2] frontal projected area above the waterline
  double As = 0.0;                        // [m^2] lateral projected area above the waterline
  double Loa = 0.0;                       // [m] length overall (moment arm of the wind yaw moment)
  double cx = 0.7, cy = 0.85, cn = 0.10;  // [-]

  // Numerical guard: speed below which U in the non-dimensional variables (v' = v/U, r' = rL/U) is
  // replaced by u_low, so the MMG terms stay finite when the ship is nearly at rest.
  double u_low = 0.05;  // [m/s]

  // Documented performance (computed by this model, checked by the tests).
  double steady_speed = 0.0;       // [m/s] steady straight speed at n_nominal, calm water
  double tactical_diameter = 0.0;  // [m] at full rudder (delta_max, laid at once) from steady_speed

  void validate() const;  // throws std::invalid_argument naming the bad field
};

// Forces and moment [N, N, N m] in body axes about the midship, split by origin (eq. 13 right-hand side).
struct MmgForces {
  Eigen::Vector3d hull = Eigen::Vector3d::Zero();
  Eigen::Vector3d propeller = Eigen::Vector3d::Zero();
  Eigen::Vector3d rudder = Eigen::Vector3d::Zero();
  Eigen::Vector3d wind = Eigen::Vector3d::Zero();
  Eigen::Vector3d wave = Eigen::Vector3d::Zero();
  Eigen::Vector3d total() const { return hull + propeller + rudder + wind + wave; }
};

// First-order Nomoto approximation T r' + r = K delta of the linearised sway-yaw dynamics.
struct NomotoParams {
  double K = 0.0;      // [1/s] rudder gain
  double T = 0.0;      // [s] time constant (T1 + T2 - T3)
  double speed = 0.0;  // [m/s] speed it was linearised at
};

class Mmg3DofModel : public VesselModel {
public:
  using StateVector = Eigen::Matrix<double, 6, 1>;  // x, y, psi, u, v, r

  explicit Mmg3DofModel(const Mmg3DofParams& p);  // validates p
  void step(const VesselInput& input, const Environment& env, double dt) override;
  bool steersBySetPoints() const override { return false; }
  double length() const override { return p_.L; }
  std::unique_ptr<VesselModel> clone() const override { return std::make_unique<Mmg3DofModel>(*this); }
  const Mmg3DofParams& params() const { return p_; }

  // Right-hand side of the state equations: eq. (13) solved for the accelerations plus the kinematics.
  StateVector derivative(const StateVector& s, double rudder, double rps, const Environment& env) const;
  // The force terms of eq. (13) at state s (rudder and rps already clamped by the caller).
  MmgForces forces(const StateVector& s, double rudder, double rps, const Environment& env) const;

  // Open-water propeller force terms for a straight run (v = r = 0) at surge u: eq. (15) thrust.
  double straightThrust(double u, double rps) const;
  // Straight-running hull resistance X(u) (negative when u > 0).
  double straightHullForce(double u) const;
  // Revolutions that hold surge speed u in calm water (thrust = resistance, solved in closed form from
  // the K_T polynomial); the feed-forward of the speed controller.
  double steadyRpsForSpeed(double u) const;
  // Nomoto K, T by linearising the sway-yaw equations at the steady straight run at `rps`.
  NomotoParams nomoto(double rps) const;

  static StateVector toVector(const VesselState& s);
  static VesselState fromVector(const StateVector& v);

private:
  Mmg3DofParams p_;
  // Precomputed constants.
  double half_rho_Ld_ = 0.0, half_rho_L2d_ = 0.0;
  double m_plus_mx_ = 0.0, m_plus_my_ = 0.0;
  Eigen::Matrix2d sway_yaw_mass_inv_;  // inverse of [[m+m_y, x_G m], [x_G m, I_zG + x_G^2 m + J_z]]
  double f_alpha_ = 0.0;               // 6.13 lambda / (lambda + 2.25), eq. (18)
  double eta_ = 0.0;                   // D_P / H_R
};

// Wu et al. (2022) eq. (16) estimates from the prismatic coefficient C_p.
inline double hankshireThrustDeduction(double Cp) {
  return 0.50 * Cp - 0.12;
}
inline double hankshireWakeFraction(double Cp) {
  return 0.7 * Cp - 0.18;
}

// Second-order wave drift coefficients of eq. (21) at lambda/L (clamped to [0, 1], see the .cpp).
Eigen::Vector3d waveDriftCoefficients(double lambda_over_L);

// Loads a 3-DOF preset: `name_or_path` is a file path (contains '/' or ends in .yaml) or a preset name
// looked up as <dir>/<name>.yaml in `preset_dir`, or, when that is empty, in the directory named by the
// environment variable ASV_VESSEL_PRESET_DIR. Throws std::runtime_error for a missing file or bad YAML,
// and std::invalid_argument naming the file, line and key for an unknown or missing key or a bad value.
Mmg3DofParams loadVesselPreset(const std::string& name_or_path, const std::string& preset_dir = "");

}  // namespace asv
