#include "analysis/LoadWork.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "physics/RollerLoads.h"
#include "io/FieldFormat.h"

namespace rollerdyn {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();


// Carts with their own loads (loads.* as lists): each value as the list of cart 1, 2, ...
std::string perCart(const Scene& sc, double (*value)(const Loads&), const char* format) {
  char buf[64];
  const int n = sc.cart_loads.empty() ? 1 : sc.carts.count;
  std::string text;
  for (int j = 0; j < n; ++j) {
    std::snprintf(buf, sizeof buf, format, value(sc.cartLoads(j)));
    text += (j ? ", " : "") + std::string(buf);
  }
  return n > 1 ? text + " (carts 1 to " + std::to_string(n) + ")" : text;
}

// The direction law and μ_r in words.
std::string loadReading(const Scene& sc) {
  const Loads& L = sc.loads;
  return "roller forces F_j1 + F_j2 = " +
         perCart(sc, [](const Loads& l) { return l.roller_force_front + l.roller_force_rear; }, "%.6g") + " N " +
         (L.roller_force_direction == RollerForceDirection::AsPrinted
              ? "of one direction as printed (loads.roller_force_direction: as_printed)"
              : "against the cart's velocity (loads.roller_force_direction: opposes_velocity)") +
         "; rolling resistance μ_r = " + perCart(sc, [](const Loads& l) { return l.rolling_resistance; }, "%.4g") +
         " of R_j1 + R_j2 = " +
         perCart(sc, [](const Loads& l) { return l.roller_normal_front + l.roller_normal_rear; }, "%.6g") + " N";
}

// The rows the works integrate over: the finite rows n, the steady window [b, e) and its span.
struct LoadRows {
  std::size_t n, b, e;
  int it;       // the t column
  double span;  // the steady window's duration [s]; NaN with under two rows
};

// Cart j's load work (trapezoidal rule on the output rows), its speed in column iv.
CartLoadWork cartLoadWork(const Scene& sc, const Table& ts, const LoadRows& r, int j, int iv) {
  const int sigma = j - 1 < int(sc.carts.side.size()) ? sc.carts.side[j - 1] : 1;
  CartLoadWork c;
  c.cart = j;
  const Loads L = sc.cartLoads(j - 1);
  auto P = [&](std::size_t i) { return rollerLoadPower(L, sigma * ts.rows[i][iv]); };
  for (std::size_t i = 1; i < r.n; ++i) {
    const double dt = ts.rows[i][r.it] - ts.rows[i - 1][r.it];
    const double p0 = P(i - 1), p1 = P(i);
    const double dW = 0.5 * (p0 + p1) * dt;
    c.work_whole_run += dW;
    if (i > r.b && i < r.e) {
      c.work_steady += dW;
      c.gross_steady += 0.5 * (std::abs(p0) + std::abs(p1)) * dt;
    }
  }
  c.power_mean_steady = r.span > 0 ? c.work_steady / r.span : kNaN;
  return c;
}

// Every cart's load work, in cart order; false when a cart's velocity column is missing.
bool addCartWorks(LoadWork& out, const Scene& sc, const Table& ts, const LoadRows& rows) {
  for (int j = 1; j <= sc.carts.count; ++j) {
    const std::string col = "v_cart_" + std::to_string(j);
    if (!ts.has(col)) return false;
    out.carts.push_back(cartLoadWork(sc, ts, rows, j, ts.index(col)));
  }
  return true;
}

// The load does almost no net work: what that falsifies, and the warning that says so.
void warnNoNetWork(const Scene& sc, LoadWork& out, double span, double sum_gross) {
  // What it falsifies depends on whether a motor drives the machine: its verdicts, or (motor
  // off) the coasting machine's run-out, which then loses energy to friction alone.
  out.consequence = sc.motor.enabled
                        ? "compaction then costs the motor nothing and every motor verdict is that of an idling machine"
                        : "compaction then takes no energy from the coasting machine (motor.enabled: false) and its "
                          "run-out is that of friction and damping alone";
  char buf[640];  // the no-net-work warning is ~390 characters
  std::snprintf(buf, sizeof buf,
                "the technological load does almost no net work: %.3g W per cart on average in the steady "
                "window, %.2g %% of the %.3g W it takes and gives back within each stroke; %s. Real "
                "compaction dissipates energy: give loads.rolling_resistance (μ_r) or "
                "loads.roller_force_direction: opposes_velocity (docs/loads.md)",
                out.power_mean_per_cart_steady, 100.0 * out.net_over_gross_steady,
                span > 0 ? sum_gross / span / sc.carts.count : kNaN, out.consequence.c_str());
  out.warning = buf;
}

}  // namespace

LoadWork computeLoadWork(const Scene& sc, const RunResult& run, const SteadyState& w) {
  LoadWork out;
  out.reading = loadReading(sc);
  const Table& ts = run.timeseries;
  if (!sc.hasRollerLoads() || !ts.has("t") || sc.carts.count < 1) return out;
  const std::size_t n = std::min(w.finite_rows, ts.rows.size());
  const std::size_t b = std::min(w.row_begin, n), e = std::min(w.row_end, n);
  const int it = ts.index("t");
  const LoadRows rows{n, b, e, it, e >= b + 2 ? ts.rows[e - 1][it] - ts.rows[b][it] : kNaN};
  double sum_steady = 0, sum_gross = 0, sum_whole = 0;
  if (!addCartWorks(out, sc, ts, rows)) return LoadWork{false, {}, 0, 0, 0, out.reading, ""};
  for (const CartLoadWork& c : out.carts) {
    sum_steady += c.work_steady;
    sum_gross += c.gross_steady;
    sum_whole += c.work_whole_run;
  }
  out.available = true;
  const double span = rows.span;
  const double whole = n >= 2 ? ts.rows[n - 1][it] - ts.rows[0][it] : kNaN;
  out.power_mean_per_cart_steady = span > 0 ? sum_steady / span / sc.carts.count : kNaN;
  out.power_mean_per_cart_whole_run = whole > 0 ? sum_whole / whole / sc.carts.count : kNaN;
  out.net_over_gross_steady = sum_gross > 0 ? sum_steady / sum_gross : kNaN;
  if (sum_gross > 0 && std::abs(out.net_over_gross_steady) < kNoNetWorkFraction) warnNoNetWork(sc, out, span, sum_gross);
  return out;
}

nlohmann::json loadWorkJson(const LoadWork& w) {
  if (!w.available) return {{"available", false}, {"reading", w.reading}};
  nlohmann::json per = nlohmann::json::array();
  for (const CartLoadWork& c : w.carts)
    per.push_back({{"cart", c.cart},
                   {"work_whole_run", jsonNumber(c.work_whole_run)},
                   {"work_steady", jsonNumber(c.work_steady)},
                   {"power_mean_steady", jsonNumber(c.power_mean_steady)},
                   {"gross_work_steady", jsonNumber(c.gross_steady)}});
  return {{"available", true},
          {"reading", w.reading},
          {"power_mean_per_cart_steady", jsonNumber(w.power_mean_per_cart_steady)},
          {"power_mean_per_cart_whole_run", jsonNumber(w.power_mean_per_cart_whole_run)},
          {"net_over_gross_steady", jsonNumber(w.net_over_gross_steady)},
          {"per_cart", per},
          {"warning", w.warning.empty() ? nlohmann::json(nullptr) : nlohmann::json(w.warning)},
          {"warning_consequence", w.consequence.empty() ? nlohmann::json(nullptr) : nlohmann::json(w.consequence)}};
}

}  // namespace rollerdyn
