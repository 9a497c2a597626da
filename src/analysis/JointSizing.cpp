#include "analysis/JointSizing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "physics/SliderCrank.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kDegPerRad = 360.0 / kTwoPi;

double given(double v) { return v > 0 ? v : kNaN; }  // 0 = not given in SizingInputs

// y(t) of the timeseries resampled at the times tq (linear; both ascending). Returned as is
// when the two grids are the same rows.
std::vector<double> resample(const std::vector<double>& t, const std::vector<double>& y,
                             const std::vector<double>& tq) {
  if (t == tq) return y;
  std::vector<double> out(tq.size(), kNaN);
  std::size_t hi = 1;
  for (std::size_t i = 0; i < tq.size(); ++i) {
    if (t.size() < 2) break;
    while (hi + 1 < t.size() && t[hi] < tq[i]) ++hi;
    const double dt = t[hi] - t[hi - 1];
    const double f = dt > 0 ? std::clamp((tq[i] - t[hi - 1]) / dt, 0.0, 1.0) : 1.0;
    out[i] = y[hi - 1] + f * (y[hi] - y[hi - 1]);
  }
  return out;
}

std::vector<double> magnitude(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> m(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) m[i] = std::hypot(x[i], y[i]);
  return m;
}

// Time mean of |y| over rows [b, e) by the trapezoidal rule; NaN when not computable.
double meanAbs(const std::vector<double>& t, const std::vector<double>& y, std::size_t b, std::size_t e) {
  if (e > t.size() || e > y.size() || e < b + 2) return kNaN;
  double area = 0;
  for (std::size_t i = b + 1; i < e; ++i) area += 0.5 * (std::abs(y[i - 1]) + std::abs(y[i])) * (t[i] - t[i - 1]);
  const double span = t[e - 1] - t[b];
  return span > 0 && std::isfinite(area) ? area / span : kNaN;
}

// One kind of joint: its name in words and the key of its rating.
struct Kind {
  const char* joint;
  const char* what;
  const char* rating_key;
};
const Kind kGuideFront{"guide_roller_front", "guide roller, front", "sizing.bearing_rating.guide_roller"};
const Kind kGuideRear{"guide_roller_rear", "guide roller, rear", "sizing.bearing_rating.guide_roller"};
const Kind kRodEnd{"rod_end", "rod end (the rod's small end on the cart's pin B)", "sizing.bearing_rating.rod_end"};
const Kind kCrankPin{"crank_pin", "crank pin (the rod's big end)", "sizing.bearing_rating.crank_pin"};
const Kind kMainBearing{"main_bearing",
                        "main bearings, resultant on the crankshaft (all bearings together; per-bearing loads "
                        "need the bearing positions)",
                        "sizing.bearing_rating.main_bearing"};
const Kind kEachMainBearing{"main_bearing",
                            "main bearings, each bearing's reaction from the crankshaft's beam statics "
                            "(crankshaft.bearing_positions)",
                            "sizing.bearing_rating.main_bearing"};

// The joint's load over rows [b, e), weighted by `speed` (empty: every instant equally).
JointSizing loadOf(const Kind& k, int cart, std::string column, std::string basis, const std::vector<double>& t,
                   const std::vector<double>& F, const std::vector<double>& speed, std::size_t b, std::size_t e,
                   double rating) {
  JointSizing j;
  j.joint = k.joint;
  j.what = k.what;
  j.cart = cart;
  j.column = std::move(column);
  j.speed_basis = std::move(basis);
  j.load = jointLoad(t, F, speed, b, e);
  j.rating = given(rating);
  j.position = kNaN;
  j.oscillation_angle = j.oscillation_frequency = j.rolling_elements_min = kNaN;
  j.life_revolutions = j.life_oscillations = j.life_hours = kNaN;
  return j;
}

// L10, and L10h by the joint's motion (JointSizing.h), or the reason there is none.
void rateLife(JointSizing& j, const Kind& k, const std::string& no_life) {
  if (!no_life.empty()) {
    j.life_reason = no_life;
    return;
  }
  if (!std::isfinite(j.rating)) {
    j.life_reason = std::string("no dynamic load rating C given (") + k.rating_key + ")";
    return;
  }
  if (!(j.load.equivalent > 0)) {
    j.life_reason = "no equivalent load P: the joint does not move or carries no load in the window";
    return;
  }
  j.life_revolutions = ratingLifeRevolutions(j.rating, j.load.equivalent);
  if (j.oscillating) {
    j.life_oscillations = oscillationLife(j.life_revolutions, j.oscillation_angle);
    if (j.oscillation_frequency > 0) j.life_hours = j.life_oscillations / (3600.0 * j.oscillation_frequency);
  } else {
    j.life_hours = ratingLifeHours(j.rating, j.load.equivalent, j.load.mean_speed);
  }
  if (!std::isfinite(j.life_hours)) {
    j.life_revolutions = j.life_oscillations = kNaN;
    j.life_reason = "no mean speed of the joint in the window";
  }
}

const char* kHoursAtMeanSpeed = "L10 = (C/P)³·10⁶ revolutions (ISO 281), L10h = L10/(n̄/2π·3600) at the mean speed n̄";

}  // namespace

std::string jointLifeNotApplicable(const std::string& motion, bool steady_reached) {
  if (motion == "turning")
    return steady_reached ? ""
                          : "steady state not reached: the run's last part is no steady running; run longer "
                            "(simulation.t_end) for the joints' lives";
  if (motion == "starting")
    return "the drive has not settled into steady running (motion: starting): run longer (simulation.t_end) "
           "for the joints' lives";
  if (motion == "coasting")
    return "the machine coasts down without its motor (motion: coasting): no steady running to wear the bearing";
  return "the drive does not turn (motion: " + (motion.empty() ? std::string("not turning") : motion) +
         "): no running to wear the bearing";
}

namespace {

// What every joint of a run is sized from: the reactions' rows t, the window's rows [b, e), the
// crank's angle and speed at those rows, the rod's swing, and why lives do not apply.
struct JointRun {
  JointRun(const Scene& scene, const Table& reactions, const Table& timeseries)
      : sc(scene), rx(reactions), ts(timeseries) {}
  const Scene& sc;
  const Table& rx;
  const Table& ts;
  std::vector<double> t, ts_t;
  std::size_t b = 0, e = 0;
  std::vector<double> crank_speed, crank_angle;
  double crank_frequency = kNaN;  // one oscillation of the rod per crank revolution: f = n̄_crank/2π
  double gamma = kNaN;            // the rod's swing amplitude asin(r/l) [rad]
  bool swing_known = false;
  std::string no_life;
};

// Cart j's guide rollers: they roll on their guide at |v|/(d/2).
void addGuideRollers(std::vector<JointSizing>& out, const JointRun& u, int j) {
  const std::string k = std::to_string(j);
  const double d = u.sc.carts.geometry.d;
  std::vector<double> roll;
  std::string roll_basis = "none (carts.geometry.d not given): every instant weighted equally";
  if (d > 0 && u.ts.has("v_cart_" + k)) {
    roll = resample(u.ts_t, u.ts.column("v_cart_" + k), u.t);
    for (double& v : roll) v = std::abs(v) / (0.5 * d);
    roll_basis = "guide-roller speed |v_cart|/(d/2)";
  }
  for (const Kind* g : {&kGuideFront, &kGuideRear}) {
    const std::string col = (g == &kGuideFront ? "N_front_" : "N_rear_") + k;
    if (!u.rx.has(col)) continue;
    JointSizing x = loadOf(*g, j, col, roll_basis, u.t, u.rx.column(col), roll, u.b, u.e, u.sc.sizing.rating_guide_roller);
    x.life_basis = "rolls on its guide at n = |v_cart|/(d/2), reversing twice per crank revolution but turning many "
                   "times between reversals: a rotating bearing; " + std::string(kHoursAtMeanSpeed) + " of the roller";
    rateLife(x, *g, roll.empty() ? "the roller's speed is not known (carts.geometry.d not given)" : u.no_life);
    out.push_back(std::move(x));
  }
}

// Cart j's rod end and crank pin: the rod's swing about the cart's pin, β̇ = ω·dβ/dθ, and the crank
// pin's rotation relative to the rod's big end, ω·(1 + σ·dβ/dθ) (the rod turns at −σ·β̇, SliderCrank.h).
struct RodSpeeds {
  std::vector<double> swing, pin_relative;  // per reactions row; empty when the rod's swing is not known
};

RodSpeeds rodSpeeds(const JointRun& u, int j) {
  RodSpeeds v;
  if (!u.swing_known) return v;
  const double r = u.sc.crank.radius, l = u.sc.rods.length;
  const int side = static_cast<std::size_t>(j - 1) < u.sc.carts.side.size() && u.sc.carts.side[j - 1] == -1 ? -1 : 1;
  const double phase = u.sc.crankPhase(j - 1);
  v.swing.resize(u.t.size());
  v.pin_relative.resize(u.t.size());
  for (std::size_t i = 0; i < u.t.size(); ++i) {
    const double dbeta = sliderCrankExact(u.crank_angle[i] + phase, r, l, side).dbeta;
    v.swing[i] = std::abs(u.crank_speed[i] * dbeta);
    v.pin_relative[i] = std::abs(u.crank_speed[i] * (1.0 + side * dbeta));
  }
  return v;
}

// The rod end oscillates through 2γ once per crank revolution: its life in oscillations.
void rateOscillatingRodEnd(JointSizing& x, const JointRun& u) {
  x.oscillating = true;
  x.oscillation_angle = 2.0 * u.gamma;
  x.oscillation_frequency = u.crank_frequency;
  x.rolling_elements_min = std::ceil(rollingElementsForOscillation(x.oscillation_angle) - 1e-9);
  x.life_basis = "oscillates through 2γ = 2·asin(r/l) = " + printfNumber("%.4g", x.oscillation_angle * kDegPerRad) +
                 "° once per crank revolution (f = " + printfNumber("%.4g", u.crank_frequency) +
                 " 1/s): L10_osc = L10·180°/(2γ) oscillations, L10 = (C/P)³·10⁶ of ISO 281 (Harris and "
                 "Kotzalas (2007)), L10h = L10_osc/(3600·f). Holds only for a bearing with at least Z = " +
                 printfNumber("%.0f", x.rolling_elements_min) +
                 " rolling elements (its critical angle 720°/Z must not exceed 2γ); with fewer the rolling "
                 "elements' loaded zones do not overlap and the conversion does not hold";
}

JointSizing rodEnd(const JointRun& u, int j, const std::vector<double>& swing) {
  const std::string k = std::to_string(j);
  JointSizing x = loadOf(kRodEnd, j, "F_rod_" + k,
                         u.swing_known ? "the rod's swing speed |β̇| = |ω_crank·dβ/dθ| about the cart's pin"
                                       : "none (the rod's swing is not known): every instant weighted equally",
                         u.t, u.rx.column("F_rod_" + k), swing, u.b, u.e, u.sc.sizing.rating_rod_end);
  if (u.swing_known) rateOscillatingRodEnd(x, u);
  rateLife(x, kRodEnd,
           u.swing_known ? u.no_life
                         : "the rod's swing is not known (it needs crank.radius < rods.length; a cam drive has no rod)");
  return x;
}

JointSizing crankPin(const JointRun& u, int j, const std::vector<double>& pin_relative) {
  const std::string k = std::to_string(j);
  JointSizing x = loadOf(kCrankPin, j, "crankpin_x_" + k + ", crankpin_y_" + k,
                         u.swing_known ? "rotation relative to the rod |ω_crank·(1 + σ·dβ/dθ)|"
                                       : "crank speed |ω_crank| (the rod's swing not known)",
                         u.t, magnitude(u.rx.column("crankpin_x_" + k), u.rx.column("crankpin_y_" + k)),
                         u.swing_known ? pin_relative : u.crank_speed, u.b, u.e, u.sc.sizing.rating_crank_pin);
  x.life_basis = "turns relative to the rod's big end at the crank's rotation less the rod's swing, "
                 "n = |ω_crank·(1 + σ·dβ/dθ)|: one relative revolution per crank revolution, never reversing "
                 "(r/l < 1); " + std::string(kHoursAtMeanSpeed);
  rateLife(x, kCrankPin, u.no_life);
  return x;
}

void addRodJoints(std::vector<JointSizing>& out, const JointRun& u, int j) {
  const std::string k = std::to_string(j);
  const RodSpeeds v = rodSpeeds(u, j);
  if (u.rx.has("F_rod_" + k)) out.push_back(rodEnd(u, j, v.swing));
  if (u.rx.has("crankpin_x_" + k) && u.rx.has("crankpin_y_" + k) && !u.crank_speed.empty())
    out.push_back(crankPin(u, j, v.pin_relative));
}

// Each main bearing's reaction (crankshaft.bearing_positions; CrankshaftBearings.h), each turning
// with the crank and rated with sizing.bearing_rating.main_bearing.
void addMainBearings(std::vector<JointSizing>& out, const JointRun& u) {
  for (int k = 1; u.rx.has("bearing_x_" + std::to_string(k)); ++k) {
    const std::string x_col = "bearing_x_" + std::to_string(k), y_col = "bearing_y_" + std::to_string(k);
    JointSizing x = loadOf(kEachMainBearing, 0, x_col + ", " + y_col, "crank speed |ω_crank|", u.t,
                           magnitude(u.rx.column(x_col), u.rx.column(y_col)), u.crank_speed, u.b, u.e,
                           u.sc.sizing.rating_main_bearing);
    x.bearing = k;
    const std::vector<double>& z = u.sc.crankshaft.bearing_positions;
    x.position = static_cast<std::size_t>(k - 1) < z.size() ? z[k - 1] : kNaN;
    x.life_basis = "each main bearing carries its share of the shaft's beam statics, turning with the crank "
                   "(every bearing rated with sizing.bearing_rating.main_bearing); " +
                   std::string(kHoursAtMeanSpeed);
    rateLife(x, kEachMainBearing, u.no_life);
    out.push_back(std::move(x));
  }
}

// The main bearings' resultant, when the shaft's bearings are not placed: one bearing carrying it all.
JointSizing mainBearingResultant(const JointRun& u) {
  JointSizing x = loadOf(kMainBearing, 0, "bearing_x, bearing_y", "crank speed |ω_crank|", u.t,
                         magnitude(u.rx.column("bearing_x"), u.rx.column("bearing_y")), u.crank_speed, u.b, u.e,
                         u.sc.sizing.rating_main_bearing);
  x.life_basis = "the life of one bearing carrying the whole resultant, turning with the crank; " +
                 std::string(kHoursAtMeanSpeed);
  rateLife(x, kMainBearing, u.no_life);
  return x;
}

// The reactions rows of the steady window, the crank's motion on them and the rod's swing.
void readJointRun(JointRun& u, const SteadyState& w, const std::string& motion) {
  u.t = u.rx.column("t");
  u.ts_t = u.ts.column("t");
  while (u.b < u.t.size() && !(u.t[u.b] >= w.t_begin)) ++u.b;
  u.e = u.b;
  while (u.e < u.t.size() && u.t[u.e] <= w.t_end) ++u.e;
  u.no_life = jointLifeNotApplicable(motion, w.reached);
  if (u.ts.has("omega_crank")) u.crank_speed = resample(u.ts_t, u.ts.column("omega_crank"), u.t);
  if (u.ts.has("phi_crank")) u.crank_angle = resample(u.ts_t, u.ts.column("phi_crank"), u.t);
  u.crank_frequency = meanAbs(u.t, u.crank_speed, u.b, u.e) / kTwoPi;
  u.gamma = u.sc.hasCamDrive() ? kNaN : rodSwingAmplitude(u.sc.crank.radius, u.sc.rods.length);
  u.swing_known = std::isfinite(u.gamma) && !u.crank_speed.empty() && !u.crank_angle.empty();
}

}  // namespace

std::vector<JointSizing> sizeJoints(const Scene& sc, const RunResult& run, const SteadyState& w,
                                    const std::string& motion) {
  std::vector<JointSizing> out;
  JointRun u{sc, run.reactions, run.timeseries};
  if (!u.rx.has("t") || u.rx.rows.empty() || !u.ts.has("t")) return out;
  readJointRun(u, w, motion);
  for (int j = 1; j <= sc.carts.count; ++j) {
    addGuideRollers(out, u, j);
    addRodJoints(out, u, j);
  }
  if (u.rx.has("bearing_x_1") && u.rx.has("bearing_y_1") && !u.crank_speed.empty())
    addMainBearings(out, u);
  else if (u.rx.has("bearing_x") && u.rx.has("bearing_y") && !u.crank_speed.empty())
    out.push_back(mainBearingResultant(u));
  return out;
}

}  // namespace rollerdyn
