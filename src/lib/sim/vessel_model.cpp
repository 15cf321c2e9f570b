// Vessel models: Lazarowska (2015) kinematic model and Wu et al. (2022) 3-DOF MMG-type model.
#include "asv_core/sim/vessel_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>
#include <Eigen/LU>

namespace asv {

namespace {

// Carries the name of the offending field so the preset loader can point at its line in the file.
class ParamError : public std::invalid_argument {
public:
  ParamError(const std::string& field, const std::string& what)
      : std::invalid_argument(field + ": " + what), field_(field) {}
  const std::string& field() const { return field_; }

private:
  std::string field_;
};

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

void requireFinite(const char* field, double v) {
  if (!std::isfinite(v))
    throw ParamError(field, "must be finite (got " + fmt(v) + ")");
}
void requirePositive(const char* field, double v) {
  requireFinite(field, v);
  if (!(v > 0.0))
    throw ParamError(field, "must be > 0 (got " + fmt(v) + ")");
}
void requireRange(const char* field, double v, double lo, double hi) {
  requireFinite(field, v);
  if (v < lo || v > hi)
    throw ParamError(field, "must be in [" + fmt(lo) + ", " + fmt(hi) + "] (got " + fmt(v) + ")");
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Environment and base class.

void Environment::validate() const {
  requireRange("wind_speed", wind_speed, 0.0, 100.0);
  requireFinite("wind_direction", wind_direction);
  requireRange("wave_height", wave_height, 0.0, 30.0);
  requireFinite("wave_direction", wave_direction);
  if (wave_height > 0.0)
    requirePositive("wave_length", wave_length);
}

void VesselModel::setState(const VesselState& s) {
  if (!s.finite())
    throw std::invalid_argument("VesselState: all fields must be finite");
  state_ = s;
  state_.psi = wrapTwoPi(s.psi);
}

// ---------------------------------------------------------------------------------------------------
// Kinematic model.

void KinematicParams::validate() const {
  requireRange("omega", omega, 1e-6, kPi);
  requireRange("t01", t01, 0.0, 3600.0);
  requirePositive("length", length);
}

KinematicModel::KinematicModel(const KinematicParams& p) : p_(p) {
  p_.validate();
  target_course_ = state_.psi;
}

void KinematicModel::setState(const VesselState& s) {
  VesselModel::setState(s);
  // The model has no sway; its yaw rate is its own (0 or +-omega), so a set state starts straight.
  state_.v = 0.0;
  state_.r = 0.0;
  target_course_ = state_.psi;
  delay_left_ = 0.0;
  manoeuvring_ = false;
}

double KinematicModel::manoeuvreTime(double dpsi) const {
  const double a = std::abs(dpsi);
  // Eq. (6): t_m = t01 + dPsi/omega - (1/omega) tg(dPsi/2).
  return p_.t01 + a / p_.omega - std::tan(a / 2.0) / p_.omega;
}

void KinematicModel::step(const VesselInput& input, const Environment&, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument("KinematicModel::step: dt must be > 0");
  if (!std::isfinite(input.course) || !std::isfinite(input.speed))
    throw std::invalid_argument("KinematicModel::step: course and speed must be finite");
  const double V = std::max(0.0, input.speed);
  const double cmd = wrapTwoPi(input.course);
  if (std::abs(wrapPi(cmd - target_course_)) > 1e-12) {
    // A new command starts the delay t01 only from a straight run; mid-manoeuvre it just moves the goal.
    if (!manoeuvring_)
      delay_left_ = p_.t01;
    manoeuvring_ = true;
    target_course_ = cmd;
  }
  state_.u = V;
  state_.v = 0.0;
  if (p_.instant) {
    // Fig. 1 of Hirayama et al.: the new course holds from the start of the step.
    manoeuvring_ = false;
    state_.psi = target_course_ = cmd;
    state_.r = 0.0;
    state_.x += V * dt * std::sin(cmd);
    state_.y += V * dt * std::cos(cmd);
    return;
  }

  // Closed-form integration of eq. (4) piece by piece (straight, turn, straight), exact for any dt.
  double psi = state_.psi;
  double left = dt;
  auto straight = [&](double t) {
    state_.x += V * t * std::sin(psi);
    state_.y += V * t * std::cos(psi);
  };
  state_.r = 0.0;
  while (left > 0.0) {
    if (manoeuvring_ && delay_left_ > 0.0) {
      const double t = std::min(left, delay_left_);
      straight(t);
      delay_left_ = (t == delay_left_) ? 0.0 : delay_left_ - t;
      left -= t;
      continue;
    }
    if (manoeuvring_) {
      const double err = wrapPi(target_course_ - psi);
      if (err == 0.0) {
        manoeuvring_ = false;
        continue;
      }
      const double w = err > 0.0 ? p_.omega : -p_.omega;
      const double t_turn = std::abs(err) / p_.omega;
      const double t = std::min(left, t_turn);
      const double psi1 = (t == t_turn) ? psi + err : psi + w * t;
      // x' = V sin psi, y' = V cos psi with psi = psi0 + w t integrate to these arcs.
      state_.x += V / w * (std::cos(psi) - std::cos(psi1));
      state_.y += V / w * (std::sin(psi1) - std::sin(psi));
      psi = psi1;
      left -= t;
      if (t == t_turn) {
        psi = target_course_;
        manoeuvring_ = false;
      } else {
        state_.r = w;
      }
      continue;
    }
    straight(left);
    left = 0.0;
  }
  state_.psi = wrapTwoPi(psi);
}

// ---------------------------------------------------------------------------------------------------
// 3-DOF model.

void Mmg3DofParams::validate() const {
  requireRange("rho", rho, 900.0, 1100.0);
  requireRange("rho_air", rho_air, 0.5, 2.0);
  requireRange("g", g, 9.0, 10.5);
  requirePositive("L", L);
  requirePositive("B", B);
  requirePositive("d", d);
  requirePositive("mass", mass);
  requireRange("xG", xG, -0.25 * L, 0.25 * L);
  requireRange("kzz", kzz, 0.05 * L, 0.5 * L);
  requireRange("mx", mx, 0.0, 1.0);
  requireRange("my", my, 0.0, 2.0);
  requireRange("Jz", Jz, 0.0, 1.0);
  requireRange("R0", R0, 1e-4, 1.0);
  const std::pair<const char*, double> derivs[] = {
      {"Xvv", Xvv},   {"Xvr", Xvr},   {"Xrr", Xrr},   {"Xvvvv", Xvvvv}, {"Yv", Yv}, {"Yr", Yr},
      {"Yvvv", Yvvv}, {"Yvvr", Yvvr}, {"Yvrr", Yvrr}, {"Yrrr", Yrrr},   {"Nv", Nv}, {"Nr", Nr},
      {"Nvvv", Nvvv}, {"Nvvr", Nvvr}, {"Nvrr", Nvrr}, {"Nrrr", Nrrr}};
  for (const auto& [field, value] : derivs)
    requireRange(field, value, -10.0, 10.0);
  requirePositive("Dp", Dp);
  requireRange("xP", xP, -1.0, 0.0);
  requireRange("tP", tP, 0.0, 0.9);
  requireRange("wP0", wP0, 0.0, 0.9);
  requireRange("wP_beta", wP_beta, 0.0, 10.0);
  requireRange("kt0", kt0, 1e-3, 2.0);
  requireRange("kt1", kt1, -5.0, 5.0);
  requireRange("kt2", kt2, -5.0, 5.0);
  requirePositive("n_max", n_max);
  requireRange("n_nominal", n_nominal, 1e-6, n_max);
  requirePositive("AR", AR);
  requireRange("lambda_R", lambda_R, 0.1, 10.0);
  requireRange("HR", HR, Dp, 10.0 * Dp + L);  // eta = Dp / HR <= 1 keeps (1 - eta) >= 0 in u_R
  requireRange("xR", xR, -1.0, 0.0);
  requireRange("tR", tR, 0.0, 0.9);
  requireRange("aH", aH, 0.0, 1.0);
  requireRange("epsilon", epsilon, 0.1, 5.0);
  requireRange("kappa", kappa, 0.0, 2.0);
  requireRange("lR", lR, -3.0, 1.0);
  requireRange("gammaR_pos", gammaR_pos, 0.0, 2.0);
  requireRange("gammaR_neg", gammaR_neg, 0.0, 2.0);
  requireRange("delta_max", delta_max, degToRad(1.0), degToRad(60.0));
  requirePositive("Af", Af);
  requirePositive("As", As);
  requirePositive("Loa", Loa);
  requireRange("cx", cx, 0.0, 2.0);
  requireRange("cy", cy, 0.0, 2.0);
  requireRange("cn", cn, 0.0, 1.0);
  requireRange("u_low", u_low, 1e-6, 1.0);
  requirePositive("steady_speed", steady_speed);
  requirePositive("tactical_diameter", tactical_diameter);
}

Mmg3DofModel::Mmg3DofModel(const Mmg3DofParams& p) : p_(p) {
  p_.validate();
  const double L = p_.L, d = p_.d, m = p_.mass;
  half_rho_Ld_ = 0.5 * p_.rho * L * d;
  half_rho_L2d_ = half_rho_Ld_ * L;
  const double mx = p_.mx * half_rho_L2d_;
  const double my = p_.my * half_rho_L2d_;
  const double Jz = p_.Jz * half_rho_L2d_ * L * L;
  const double IzG = m * p_.kzz * p_.kzz;
  m_plus_mx_ = m + mx;
  m_plus_my_ = m + my;
  Eigen::Matrix2d M;
  M << m + my, p_.xG * m, p_.xG * m, IzG + p_.xG * p_.xG * m + Jz;
  sway_yaw_mass_inv_ = M.inverse();
  f_alpha_ = 6.13 * p_.lambda_R / (p_.lambda_R + 2.25);
  eta_ = p_.Dp / p_.HR;
}

Mmg3DofModel::StateVector Mmg3DofModel::toVector(const VesselState& s) {
  StateVector v;
  v << s.x, s.y, s.psi, s.u, s.v, s.r;
  return v;
}

VesselState Mmg3DofModel::fromVector(const StateVector& v) {
  VesselState s;
  s.x = v(0);
  s.y = v(1);
  s.psi = v(2);
  s.u = v(3);
  s.v = v(4);
  s.r = v(5);
  return s;
}

Eigen::Vector3d waveDriftCoefficients(double lambda_over_L) {
  // The cubic fits of eq. (21) turn back up beyond lambda/L ~ 1 (C_yw grows again, C_xw goes strongly
  // negative by 2), which is extrapolation; long waves carry little drift, so hold the lambda/L = 1 value.
  const double x = std::clamp(lambda_over_L, 0.0, 1.0);
  const double x2 = x * x, x3 = x2 * x;
  return {0.05 - 0.2 * x + 0.75 * x2 - 0.51 * x3,     // C_xw
          0.46 + 6.83 * x - 15.56 * x2 + 8.44 * x3,   // C_yw
          -0.11 + 0.68 * x - 0.79 * x2 + 0.21 * x3};  // C_nw
}

MmgForces Mmg3DofModel::forces(const StateVector& s, double delta, double n, const Environment& env) const {
  const double psi = s(2), u = s(3), v = s(4), r = s(5);
  const double L = p_.L;
  const double U = std::sqrt(u * u + v * v);
  const double Ug = std::max(U, p_.u_low);
  const double inv_Ug = 1.0 / Ug;
  MmgForces f;

  // Hull, eq. (14): X_H = X(u) + X_vv v^2 + X_vr v r + X_rr r r, Y_H = Y_v v + Y_r r, N_H = N_v v + N_r r.
  // Written dimensionally from the MMG primes: 1/2 rho L d U^2 Y'_v v' = 1/2 rho L d U Y'_v v, etc.; the
  // higher-order MMG terms (zero for eq. 14 as printed) use Ug so they stay finite near rest.
  const double rL = r * L;
  const double v2 = v * v, rL2 = rL * rL;
  f.hull(0) = half_rho_Ld_ * (-p_.R0 * u * std::abs(u) + p_.Xvv * v2 + p_.Xvr * v * rL + p_.Xrr * rL2 +
                              p_.Xvvvv * v2 * v2 * inv_Ug * inv_Ug);
  f.hull(1) = half_rho_Ld_ *
              ((p_.Yv * v + p_.Yr * rL) * U +
               (p_.Yvvv * v2 * v + p_.Yvvr * v2 * rL + p_.Yvrr * v * rL2 + p_.Yrrr * rL2 * rL) * inv_Ug);
  f.hull(2) = half_rho_L2d_ *
              ((p_.Nv * v + p_.Nr * rL) * U +
               (p_.Nvvv * v2 * v + p_.Nvvr * v2 * rL + p_.Nvrr * v * rL2 + p_.Nrrr * rL2 * rL) * inv_Ug);

  // Propeller, eq. (15)-(16): X_P = (1 - t_P) rho n^2 D^4 K_T(J_P), J_P = u_P / (n D),
  // u_P = u (1 - w_P), w_P = w_P0 exp(-c beta_P^2), beta_P = beta - x'_P r'. Wu writes u_P = U (1 - w_P);
  // the MMG standard uses the surge u, which is what the propeller disc sees.
  // K_T n^2 D^2 = a0 n^2 D^2 + a1 n D u_P + a2 u_P^2 avoids dividing by n at rest; it is clamped at zero
  // beyond the zero-thrust advance ratio (windmilling drag is not modelled), so n = 0 gives no force.
  const double beta = (U > 0.0) ? std::atan2(-v, u) : 0.0;  // drift angle
  const double r_nd = rL * inv_Ug;                          // r'
  const double beta_P = beta - p_.xP * r_nd;
  const double wP = p_.wP0 * std::exp(-p_.wP_beta * beta_P * beta_P);
  const double uP = u * (1.0 - wP);
  const double nD = n * p_.Dp;
  const double ktn2d2 = std::max(0.0, p_.kt0 * nD * nD + p_.kt1 * nD * uP + p_.kt2 * uP * uP);
  const double thrust = p_.rho * p_.Dp * p_.Dp * ktn2d2;
  f.propeller(0) = (1.0 - p_.tP) * thrust;  // Y_P = N_P = 0 (eq. 15)

  // Rudder inflow (Wu: "the key ... is to determine the effective flow velocity and the effective rudder
  // angle"; the paper gives no formula, we use the MMG standard, Yasukawa & Yoshimura 2015 eq. 25-29):
  // u_R = eps u_P sqrt(eta {1 + kappa (sqrt(1 + 8 K_T / (pi J^2)) - 1)}^2 + (1 - eta)), multiplied through
  // by u_P so the bollard case J = 0 is regular; v_R = U gamma_R beta_R, beta_R = beta - l'_R r'.
  const double slip = std::sqrt(uP * uP + 8.0 * ktn2d2 / kPi);
  const double core = uP + p_.kappa * (slip - uP);
  const double uR = p_.epsilon * std::sqrt(eta_ * core * core + (1.0 - eta_) * uP * uP);
  const double beta_R = beta - p_.lR * r_nd;
  const double vR = U * (beta_R < 0.0 ? p_.gammaR_neg : p_.gammaR_pos) * beta_R;
  const double UR2 = uR * uR + vR * vR;
  const double alpha_R = delta - std::atan2(vR, uR);
  // Eq. (18), Fujii's normal force: F_N = 1/2 rho (6.13 lambda / (lambda + 2.25)) A_R U_R^2 sin alpha_R,
  // lambda the rudder aspect ratio and A_d the rudder area (the paper's glossary mislabels both).
  const double FN = 0.5 * p_.rho * f_alpha_ * p_.AR * UR2 * std::sin(alpha_R);
  const double sd = std::sin(delta), cd = std::cos(delta);
  // Eq. (17). The MMG standard writes N_R = -(x_R + a_H x_H) F_N cos(delta); Wu's form takes x_H = x_R.
  f.rudder(0) = -(1.0 - p_.tR) * FN * sd;
  f.rudder(1) = -(1.0 + p_.aH) * FN * cd;
  f.rudder(2) = -(1.0 + p_.aH) * p_.xR * L * FN * cd;

  if (env.wind_speed > 0.0) {
    // Eq. (19) with the relative wind (u_rw, v_rw) in body axes and Fossen's (2011, sec. 8.1) coefficients
    // C_X = -c_x cos(gamma), C_Y = c_y sin(gamma), C_N = c_n sin(2 gamma), gamma = -atan2(v_rw, u_rw).
    // Eq. (19) prints N without a length; a moment needs one, so N carries L_oa (Fossen, Isherwood).
    // Using V^2 cos(gamma) = V u_rw and V^2 sin(gamma) = -V v_rw avoids the trigonometry.
    const double rel = env.wind_direction - psi;  // where the wind comes from, relative to the bow
    const double urw = u + env.wind_speed * std::cos(rel);
    const double vrw = v + env.wind_speed * std::sin(rel);
    const double Vrw = std::sqrt(urw * urw + vrw * vrw);
    const double q = 0.5 * p_.rho_air;
    f.wind(0) = q * p_.Af * (-p_.cx) * Vrw * urw;
    f.wind(1) = q * p_.As * p_.cy * (-Vrw * vrw);
    f.wind(2) = q * p_.As * p_.Loa * p_.cn * (-2.0 * urw * vrw);
  }

  if (env.wave_height > 0.0) {
    // Eq. (20)-(21). chi is the encounter angle: wave propagation direction relative to the heading
    // (0 = following sea), so drift pushes the ship the way the waves travel. Eq. (20) prints N with a
    // single L; the drift moment scales with L^2 (Daidola et al. 1986, Fossen 2011), as used here.
    const double xi = 0.5 * env.wave_height;
    const double chi = env.wave_direction + kPi - psi;
    const Eigen::Vector3d C = waveDriftCoefficients(env.wave_length / L);
    const double q = 0.5 * p_.rho * p_.g * L * xi * xi;
    const double sc = std::sin(chi);
    f.wave(0) = q * C(0) * std::cos(chi);
    f.wave(1) = q * C(1) * sc;
    f.wave(2) = q * L * C(2) * sc;
  }
  return f;
}

Mmg3DofModel::StateVector Mmg3DofModel::derivative(const StateVector& s, double delta, double n,
                                                   const Environment& env) const {
  const Eigen::Vector3d F = forces(s, delta, n, env).total();
  const double psi = s(2), u = s(3), v = s(4), r = s(5);
  const double m = p_.mass, xG = p_.xG;
  // Eq. (13), written about the midship as in the MMG standard (Yasukawa & Yoshimura 2015 eq. 4); x_G = 0
  // gives Wu's form. Eq. (13) prints "(m + m_y) v' - (m + m_x) r u"; the centripetal term enters the sway
  // equation with a plus sign (Newton in the rotating body frame), which is what is solved here.
  StateVector ds;
  const double sp = std::sin(psi), cp = std::cos(psi);
  ds(0) = u * sp + v * cp;
  ds(1) = u * cp - v * sp;
  ds(2) = r;
  ds(3) = (F(0) + m_plus_my_ * v * r + xG * m * r * r) / m_plus_mx_;
  const Eigen::Vector2d vr =
      sway_yaw_mass_inv_ * Eigen::Vector2d(F(1) - m_plus_mx_ * u * r, F(2) - xG * m * u * r);
  ds(4) = vr(0);
  ds(5) = vr(1);
  return ds;
}

void Mmg3DofModel::step(const VesselInput& input, const Environment& env, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument("Mmg3DofModel::step: dt must be > 0");
  if (!std::isfinite(input.rudder) || !std::isfinite(input.propeller_rps))
    throw std::invalid_argument("Mmg3DofModel::step: rudder and propeller_rps must be finite");
  const double delta = std::clamp(input.rudder, -p_.delta_max, p_.delta_max);
  const double n = std::clamp(input.propeller_rps, 0.0, p_.n_max);
  // Eq. (22), classical RK4 with the input held over the step. Eq. (22) prints K4 at x_n + 0.5 h and
  // y_n + 0.5 h K3, a typo: that is not fourth order; K4 = f(x_n + h, y_n + h K3) is.
  const StateVector y = toVector(state_);
  const StateVector k1 = derivative(y, delta, n, env);
  const StateVector k2 = derivative(y + 0.5 * dt * k1, delta, n, env);
  const StateVector k3 = derivative(y + 0.5 * dt * k2, delta, n, env);
  const StateVector k4 = derivative(y + dt * k3, delta, n, env);
  const StateVector y1 = y + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  state_ = fromVector(y1);
  state_.psi = wrapTwoPi(state_.psi);
}

double Mmg3DofModel::straightThrust(double u, double n) const {
  StateVector s = StateVector::Zero();
  s(3) = u;
  return forces(s, 0.0, n, Environment{}).propeller(0);
}

double Mmg3DofModel::straightHullForce(double u) const {
  StateVector s = StateVector::Zero();
  s(3) = u;
  return forces(s, 0.0, 0.0, Environment{}).hull(0);
}

double Mmg3DofModel::steadyRpsForSpeed(double u) const {
  if (!(u > 0.0))
    return 0.0;
  // (1 - t_P) rho D^2 (a0 n^2 D^2 + a1 n D u_P + a2 u_P^2) = 1/2 rho L d R0 u^2, a quadratic in n.
  const double uP = u * (1.0 - p_.wP0);
  const double D = p_.Dp;
  const double T = half_rho_Ld_ * p_.R0 * u * u / (1.0 - p_.tP) / (p_.rho * D * D);
  const double a = p_.kt0 * D * D, b = p_.kt1 * D * uP, c = p_.kt2 * uP * uP - T;
  return (-b + std::sqrt(std::max(0.0, b * b - 4.0 * a * c))) / (2.0 * a);
}

NomotoParams Mmg3DofModel::nomoto(double n) const {
  // Steady speed at n: thrust - resistance falls with u, so bisect on its sign.
  double lo = 0.0, hi = 1.0;
  auto net = [&](double u) { return straightThrust(u, n) + straightHullForce(u); };
  while (net(hi) > 0.0 && hi < 1e3)
    hi *= 2.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (net(mid) > 0.0 ? lo : hi) = mid;
  }
  const double u0 = 0.5 * (lo + hi);
  StateVector s0 = StateVector::Zero();
  s0(3) = u0;
  const Environment calm;
  // Central differences: the flow straightening gamma_R switches at beta_R = 0, so one-sided ones differ.
  const double hv = 1e-4 * std::max(u0, 1e-3), hr = hv / p_.L, hd = 1e-4;
  auto col = [&](int idx, double h) {
    StateVector sp = s0, sm = s0;
    sp(idx) += h;
    sm(idx) -= h;
    return ((derivative(sp, 0.0, n, calm) - derivative(sm, 0.0, n, calm)) / (2.0 * h)).eval();
  };
  const StateVector dv = col(4, hv), dr = col(5, hr);
  const StateVector dd = (derivative(s0, hd, n, calm) - derivative(s0, -hd, n, calm)) / (2.0 * hd);
  const double a11 = dv(4), a12 = dr(4), a21 = dv(5), a22 = dr(5), bv = dd(4), br = dd(5);
  const double det = a11 * a22 - a12 * a21;
  const double num = a21 * bv - a11 * br;
  NomotoParams out;
  out.speed = u0;
  // r/delta = (br s + num) / (s^2 - tr s + det) = K (1 + T3 s) / ((1 + T1 s)(1 + T2 s)).
  out.K = num / det;
  out.T = -(a11 + a22) / det - br / num;
  return out;
}

// ---------------------------------------------------------------------------------------------------
// Preset loader.

namespace {

struct KeySpec {
  const char* key;    // YAML key
  const char* field;  // Mmg3DofParams field, as validate() names it
  double Mmg3DofParams::*member;
  double scale;  // YAML unit -> SI
};

struct SectionSpec {
  const char* name;
  std::vector<KeySpec> keys;
};

const std::vector<SectionSpec>& presetSchema() {
  using P = Mmg3DofParams;
  static const std::vector<SectionSpec> schema = {
      {"environment",
       {{"rho", "rho", &P::rho, 1.0}, {"rho_air", "rho_air", &P::rho_air, 1.0}, {"g", "g", &P::g, 1.0}}},
      {"particulars",
       {{"L", "L", &P::L, 1.0},
        {"B", "B", &P::B, 1.0},
        {"d", "d", &P::d, 1.0},
        {"mass", "mass", &P::mass, 1.0},
        {"xG", "xG", &P::xG, 1.0},
        {"kzz", "kzz", &P::kzz, 1.0}}},
      {"added_mass", {{"mx", "mx", &P::mx, 1.0}, {"my", "my", &P::my, 1.0}, {"Jz", "Jz", &P::Jz, 1.0}}},
      {"hull",
       {{"R0", "R0", &P::R0, 1.0},
        {"Xvv", "Xvv", &P::Xvv, 1.0},
        {"Xvr", "Xvr", &P::Xvr, 1.0},
        {"Xrr", "Xrr", &P::Xrr, 1.0},
        {"Xvvvv", "Xvvvv", &P::Xvvvv, 1.0},
        {"Yv", "Yv", &P::Yv, 1.0},
        {"Yr", "Yr", &P::Yr, 1.0},
        {"Yvvv", "Yvvv", &P::Yvvv, 1.0},
        {"Yvvr", "Yvvr", &P::Yvvr, 1.0},
        {"Yvrr", "Yvrr", &P::Yvrr, 1.0},
        {"Yrrr", "Yrrr", &P::Yrrr, 1.0},
        {"Nv", "Nv", &P::Nv, 1.0},
        {"Nr", "Nr", &P::Nr, 1.0},
        {"Nvvv", "Nvvv", &P::Nvvv, 1.0},
        {"Nvvr", "Nvvr", &P::Nvvr, 1.0},
        {"Nvrr", "Nvrr", &P::Nvrr, 1.0},
        {"Nrrr", "Nrrr", &P::Nrrr, 1.0}}},
      {"propeller",
       {{"Dp", "Dp", &P::Dp, 1.0},
        {"xP", "xP", &P::xP, 1.0},
        {"tP", "tP", &P::tP, 1.0},
        {"wP0", "wP0", &P::wP0, 1.0},
        {"wP_beta", "wP_beta", &P::wP_beta, 1.0},
        {"kt0", "kt0", &P::kt0, 1.0},
        {"kt1", "kt1", &P::kt1, 1.0},
        {"kt2", "kt2", &P::kt2, 1.0},
        {"n_max", "n_max", &P::n_max, 1.0},
        {"n_nominal", "n_nominal", &P::n_nominal, 1.0}}},
      {"rudder",
       {{"AR", "AR", &P::AR, 1.0},
        {"lambda_R", "lambda_R", &P::lambda_R, 1.0},
        {"HR", "HR", &P::HR, 1.0},
        {"xR", "xR", &P::xR, 1.0},
        {"tR", "tR", &P::tR, 1.0},
        {"aH", "aH", &P::aH, 1.0},
        {"epsilon", "epsilon", &P::epsilon, 1.0},
        {"kappa", "kappa", &P::kappa, 1.0},
        {"lR", "lR", &P::lR, 1.0},
        {"gammaR_pos", "gammaR_pos", &P::gammaR_pos, 1.0},
        {"gammaR_neg", "gammaR_neg", &P::gammaR_neg, 1.0},
        {"delta_max_deg", "delta_max", &P::delta_max, kPi / 180.0}}},
      {"wind",
       {{"Af", "Af", &P::Af, 1.0},
        {"As", "As", &P::As, 1.0},
        {"Loa", "Loa", &P::Loa, 1.0},
        {"cx", "cx", &P::cx, 1.0},
        {"cy", "cy", &P::cy, 1.0},
        {"cn", "cn", &P::cn, 1.0}}},
      {"numerics", {{"u_low", "u_low", &P::u_low, 1.0}}},
      {"documented",
       {{"steady_speed", "steady_speed", &P::steady_speed, 1.0},
        {"tactical_diameter", "tactical_diameter", &P::tactical_diameter, 1.0}}},
  };
  return schema;
}

bool looksLikePath(const std::string& s) {
  return s.find('/') != std::string::npos || (s.size() > 5 && s.compare(s.size() - 5, 5, ".yaml") == 0);
}

}  // namespace

Mmg3DofParams loadVesselPreset(const std::string& name_or_path, const std::string& preset_dir) {
  std::string path = name_or_path;
  if (!looksLikePath(name_or_path)) {
    std::string dir = preset_dir;
    if (dir.empty()) {
      // The environment overrides the presets shipped with the package (ASV_CORE_PRESET_DIR is set
      // by CMake to src/config/vessels, ASV_CORE_INSTALLED_PRESET_DIR to the installed copy).
      const char* envdir = std::getenv("ASV_VESSEL_PRESET_DIR");
      if (envdir != nullptr && *envdir != '\0') {
        dir = envdir;
      } else {
#ifdef ASV_CORE_PRESET_DIR
        dir = std::filesystem::is_directory(ASV_CORE_PRESET_DIR) ? ASV_CORE_PRESET_DIR
                                                                 : ASV_CORE_INSTALLED_PRESET_DIR;
#else
        throw std::runtime_error("loadVesselPreset: '" + name_or_path +
                                 "' is a preset name but no preset directory was given and "
                                 "ASV_VESSEL_PRESET_DIR is not set");
#endif
      }
    }
    path = dir + "/" + name_or_path + ".yaml";
  }
  if (!std::ifstream(path).good())
    throw std::runtime_error("loadVesselPreset: cannot open " + path);
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": YAML error: " + e.what());
  }
  auto where = [&](const YAML::Node& n) { return path + ":" + std::to_string(n.Mark().line + 1); };
  if (!root.IsMap())
    throw std::invalid_argument(path + ": top level must be a map");

  Mmg3DofParams p;
  std::map<std::string, YAML::Mark> marks;  // field -> where it was set, to place validation errors
  const auto& schema = presetSchema();
  const char* top_keys[] = {"format", "name", "description", "model"};
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    bool known = std::find_if(std::begin(top_keys), std::end(top_keys),
                              [&](const char* k) { return key == k; }) != std::end(top_keys);
    known = known ||
            std::any_of(schema.begin(), schema.end(), [&](const SectionSpec& s) { return key == s.name; });
    if (!known)
      throw std::invalid_argument(where(it->first) + ": unknown key '" + key + "'");
  }
  for (const char* k : top_keys)
    if (!root[k])
      throw std::invalid_argument(path + ": missing key '" + k + "'");
  if (root["format"].as<std::string>() != "1")
    throw std::invalid_argument(where(root["format"]) + ": unsupported format (expected 1)");
  if (root["model"].as<std::string>() != "mmg3dof")
    throw std::invalid_argument(where(root["model"]) + ": model must be 'mmg3dof'");
  p.name = root["name"].as<std::string>();
  p.description = root["description"].as<std::string>();

  for (const SectionSpec& sec : schema) {
    const YAML::Node node = root[sec.name];
    if (!node)
      throw std::invalid_argument(path + ": missing section '" + sec.name + "'");
    if (!node.IsMap())
      throw std::invalid_argument(where(node) + ": section '" + sec.name + "' must be a map");
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string key = it->first.as<std::string>();
      auto spec =
          std::find_if(sec.keys.begin(), sec.keys.end(), [&](const KeySpec& k) { return key == k.key; });
      if (spec == sec.keys.end())
        throw std::invalid_argument(where(it->first) + ": unknown key '" + key + "' in section '" + sec.name +
                                    "'");
      double value = 0.0;
      try {
        value = it->second.as<double>();
      } catch (const YAML::Exception&) {
        throw std::invalid_argument(where(it->second) + ": key '" + key + "' must be a number");
      }
      p.*(spec->member) = value * spec->scale;
      marks[spec->field] = it->first.Mark();
    }
    for (const KeySpec& k : sec.keys)
      if (!node[k.key])
        throw std::invalid_argument(where(node) + ": missing key '" + k.key + "' in section '" + sec.name +
                                    "'");
  }
  try {
    p.validate();
  } catch (const ParamError& e) {
    auto m = marks.find(e.field());
    const std::string loc = m != marks.end() ? path + ":" + std::to_string(m->second.line + 1) : path;
    throw std::invalid_argument(loc + ": invalid value: " + e.what());
  }
  return p;
}

}  // namespace asv
