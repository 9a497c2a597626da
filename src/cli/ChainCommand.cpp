// `rollerdyn chain [--J1 ..] [--J2 ..] [--k ..] [--b ..] [--M1 ..] [--alpha ..] [--Mc ..] [--omega ..]
//  [--t-end ..] [--out DIR]`: Dyomin's two rotors on an elastic chain, simulated (Simbody, the
// project's ElasticCoupling) beside the paper's closed-form response eq. (26)-(36), as printed
// and corrected (src/studies/TwoRotorChain.h). Parameters are command-line options, not a scene
// file: the system has eight numbers and none of the installation's parts.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "io/AtomicFile.h"
#include "report/Gnuplot.h"
#include "report/OutputDir.h"
#include "studies/TwoRotorChain.h"

namespace rollerdyn::cli {

namespace {

struct ChainArgs {
  TwoRotorChainParams p;
  std::string out_dir = "out/two-rotor-chain";
};

// chain.json: the parameters, the derived values, the harmonic amplitudes as printed and
// corrected, the last period's swing and mean, the errors of both closed forms.
nlohmann::json chainJson(const TwoRotorChainParams& p, const ChainComparison& c) {
  const TwoRotorChainDerived& d = c.derived;
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json j;
  j["parameters"] = {{"J1", p.J1}, {"J2", p.J2}, {"k", p.k}, {"b", p.b}, {"M1", p.M1}, {"alpha", p.alpha},
                     {"Mc", d.Mc}, {"omega", p.omega}, {"t_end", d.t_end}, {"output_step", d.output_step},
                     {"accuracy", p.accuracy}};
  j["derived"] = {{"delta1", d.delta1}, {"p0", d.p0}, {"p1", num(d.p1)}, {"Phi0", d.Phi0},
                  {"p0_over_omega", d.p0 / p.omega}};
  const char* hn[] = {"1", "2", "3", "5"};
  for (int i = 0; i < 4; ++i)
    j["harmonic_amplitudes"][std::string("n") + hn[i]] = {{"printed", c.harmonics.printed[i]},
                                                           {"corrected", c.harmonics.corrected[i]}};
  j["steady_last_period"] = {{"swing_sim", c.swing_sim}, {"swing_corrected", c.swing_corrected},
                             {"swing_printed", c.swing_printed}, {"mean_sim", c.mean_sim},
                             {"Phi0", c.mean_closed}, {"max_err_corrected", c.max_err_corrected_steady},
                             {"max_err_printed", c.max_err_printed_steady}};
  j["full_run"] = {{"max_err_corrected", c.max_err_corrected_full}, {"max_err_printed", num(c.max_err_printed_full)}};
  j["warnings"] = c.resonance_warnings;
  return j;
}

// The chain's twist over the last three periods: the simulation and both closed forms.
void drawChainTwist(const TwoRotorChainParams& p, const ChainComparison& c, const std::string& stem) {
  PlotSpec spec;
  spec.title = "Dyomin (two rotors): twist of the chain, last three periods";
  spec.xlabel = "t [s]";
  spec.ylabel = "psi = phi1 - phi2 [rad]";
  const double t0 = c.derived.t_end - 3 * 2 * M_PI / p.omega;
  const char* cols[] = {"psi_sim", "psi_corrected", "psi_printed"};
  const char* titles[] = {"simulation (Simbody)", "closed form, corrected", "closed form as printed (26)"};
  for (int k = 0; k < 3; ++k) {
    PlotSeries s;
    s.title = titles[k];
    const int it = c.table.index("t"), iy = c.table.index(cols[k]);
    for (const auto& row : c.table.rows)
      if (row[it] >= t0) {
        s.x.push_back(row[it]);
        s.y.push_back(row[iy]);
      }
    spec.series.push_back(s);
  }
  renderPlot(spec, stem);
}

void printChain(const TwoRotorChainParams& p, const ChainComparison& c) {
  const TwoRotorChainDerived& d = c.derived;
  std::printf("two rotors on an elastic chain (Dyomin (two rotors)): delta1 = %.4g 1/s, p0 = %.4g rad/s, p0/omega = %.4g\n",
              d.delta1, d.p0, d.p0 / p.omega);
  std::printf("harmonic amplitudes [rad]   n=1        n=2        n=3        n=5\n");
  std::printf("  printed (16)-(28)       %.4e %.4e %.4e %.4e\n", c.harmonics.printed[0], c.harmonics.printed[1],
              c.harmonics.printed[2], c.harmonics.printed[3]);
  std::printf("  corrected               %.4e %.4e %.4e %.4e\n", c.harmonics.corrected[0],
              c.harmonics.corrected[1], c.harmonics.corrected[2], c.harmonics.corrected[3]);
  std::printf("steady twist swing [rad]: simulation %.6e, corrected %.6e, printed %.6e\n", c.swing_sim,
              c.swing_corrected, c.swing_printed);
  std::printf("mean twist [rad]: simulation %.6e, Phi0 (eq. (11)) %.6e\n", c.mean_sim, c.mean_closed);
  std::printf("max |psi_sim - psi_closed| [rad]: corrected %.3e (steady) %.3e (whole run); printed %.3e (steady)\n",
              c.max_err_corrected_steady, c.max_err_corrected_full, c.max_err_printed_steady);
}

int runChain(const ChainArgs& a) {
  prepareOutputDir(a.out_dir);  // before the run: a bad --out fails now
  const ChainComparison c = compareTwoRotorChain(a.p);
  writeCsvAtomic(a.out_dir + "/chain.csv", c.table);
  writeFileAtomic(a.out_dir + "/chain.json", chainJson(a.p, c).dump(2) + "\n");
  if (gnuplotAvailable()) drawChainTwist(a.p, c, a.out_dir + "/chain_twist");
  printChain(a.p, c);
  for (const std::string& w : c.resonance_warnings) std::cerr << "rollerdyn: warning: resonance: " << w << "\n";
  std::cout << "outputs in " << a.out_dir << "/\n";
  return 0;
}

}  // namespace

Subcommand addChainCommand(CLI::App& app) {
  auto a = std::make_shared<ChainArgs>();
  CLI::App* cmd = app.add_subcommand(
      "chain", "Dyomin (two rotors): two rotors on an elastic chain, simulation vs the closed-form response eq. (26)-(36)");
  TwoRotorChainParams& p = a->p;
  cmd->add_option("--J1", p.J1, "driving rotor inertia [kg·m²] (default 73.6: Loveikin, Pochka, Romasevych's (2018) motor side)");
  cmd->add_option("--J2", p.J2, "driven rotor inertia [kg·m²] (default 95)");
  cmd->add_option("--k", p.k, "chain stiffness [N·m/rad] (default 2e5)");
  cmd->add_option("--b", p.b, "chain damping [N·m·s/rad] (default 2000)");
  cmd->add_option("--M1", p.M1, "drive torque amplitude M1 of eq. (8) [N·m] (default 1000)");
  cmd->add_option("--alpha", p.alpha, "angle alpha of eq. (8) [rad] (default 0.3)");
  cmd->add_option("--Mc", p.Mc, "resisting torque [N·m] (default: the mean drive torque M1(pi-2alpha)/pi)");
  cmd->add_option("--omega", p.omega, "frequency of the drive torque [rad/s] (default 10.47)");
  cmd->add_option("--t-end", p.t_end, "simulated time [s] (default: until the transient has decayed 1e9 times)");
  cmd->add_option("--out", a->out_dir, "output folder (default out/two-rotor-chain)");
  cmd->footer("Examples:\n  rollerdyn chain\n  rollerdyn chain --omega 23.15   # p0 = 3*omega: third-harmonic resonance");
  return {cmd, [a] { return runChain(*a); }};
}

}  // namespace rollerdyn::cli
