#include "modes/ChainModes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "physics/CartReducedInertia.h"
#include "physics/SliderCrank.h"
#include "physics/TorsionalChain.h"

namespace rollerdyn::modes {
namespace {

void checkChain(const std::vector<double>& J, const std::vector<double>& c) {
  if (J.empty() || c.size() + 1 != J.size())
    throw std::invalid_argument("torsional chain: n rotors need n - 1 springs");
  for (double v : J)
    if (!(v > 0)) throw std::invalid_argument("torsional chain: every rotor needs an inertia > 0");
  for (double v : c)
    if (!(v > 0)) throw std::invalid_argument("torsional chain: every spring needs a stiffness > 0");
}

struct Eigenpairs {
  Eigen::VectorXd lambda;   // ascending
  Eigen::MatrixXd vectors;  // M-orthonormal columns
};

Eigenpairs solveChain(const std::vector<double>& J, const std::vector<double>& c) {
  checkChain(J, c);
  const int n = int(J.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n), K = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) M(i, i) = J[i];
  for (int i = 0; i + 1 < n; ++i) {
    K(i, i) += c[i];
    K(i + 1, i + 1) += c[i];
    K(i, i + 1) -= c[i];
    K(i + 1, i) -= c[i];
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  if (es.info() != Eigen::Success) throw std::runtime_error("torsional chain: the eigen-solution failed");
  return {es.eigenvalues(), es.eigenvectors()};
}

std::string springName(const Scene& sc, const TorsionalChainLayout& chain, bool elastic, int spring) {
  if (elastic && spring == 0) return "motor side against the crankshaft (coupling)";
  const int k = elastic ? spring - 1 : spring;
  return "throws of carts " + std::to_string(chain.cart_of_throw[k] + 1) + " and " +
         std::to_string(chain.cart_of_throw[k + 1] + 1) + " against each other (shaft segment between them)";
}

}  // namespace

std::vector<double> chainNaturalFrequencies(const std::vector<double>& J, const std::vector<double>& c) {
  const Eigenpairs e = solveChain(J, c);
  std::vector<double> p;
  for (int i = 0; i < e.lambda.size(); ++i) p.push_back(std::sqrt(std::max(e.lambda[i], 0.0)));
  return p;
}

double holzerResidual(const std::vector<double>& J, const std::vector<double>& c, double p) {
  checkChain(J, c);
  // Holzer's table: the amplitude of rotor i and the torque in the spring behind it; the inertia
  // torque J·p²·θ of each rotor adds to the torque passed on, which twists the next spring.
  double theta = 1.0, torque = 0.0;
  for (size_t i = 0; i < J.size(); ++i) {
    torque += J[i] * p * p * theta;
    if (i < c.size()) theta -= torque / c[i];
  }
  return torque;
}

std::vector<double> holzerFrequencies(const std::vector<double>& J, const std::vector<double>& c, double p_max,
                                      int steps) {
  std::vector<double> roots;
  double a = p_max / steps, Ra = holzerResidual(J, c, a);
  for (int i = 2; i <= steps; ++i) {
    const double b = p_max * i / steps, Rb = holzerResidual(J, c, b);
    if ((Ra < 0) != (Rb < 0)) {
      double lo = a, hi = b, Rlo = Ra;
      while (hi - lo > 1e-12 * hi) {
        const double mid = 0.5 * (lo + hi), Rm = holzerResidual(J, c, mid);
        if ((Rm < 0) == (Rlo < 0)) {
          lo = mid;
          Rlo = Rm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(0.5 * (lo + hi));
    }
    a = b;
    Ra = Rb;
  }
  return roots;
}

void chainAtAngle(const Scene& sc, double phi, std::vector<double>& J, std::vector<double>& c) {
  const TorsionalChainLayout chain = torsionalChainLayout(sc);
  const bool elastic = sc.coupling.type == CouplingType::Elastic;
  J.clear();
  c.clear();
  if (elastic) {
    J.push_back(sc.motorSideInertia());
    c.push_back(sc.coupling.stiffness);
  }
  const double r = sc.crank.radius;
  const double pin_share = sc.rods.model == RodModel::Split ? 0.5 * sc.rods.mass * r * r : 0.0;
  for (size_t k = 0; k < chain.inertia.size(); ++k) {
    const int j = chain.cart_of_throw[k];
    const SliderCrankPose pose = sliderCrankExact(phi + sc.crankPhase(j), r, sc.rods.length, sc.carts.side[j]);
    double Jk = chain.inertia[k] + pin_share + cartReducedInertia(sc.cartMassWithRodShare(j), sc.rods, pose);
    if (k == 0 && !elastic) Jk += sc.motorSideInertia();
    J.push_back(Jk);
  }
  c.insert(c.end(), chain.stiffness.begin(), chain.stiffness.end());
}

namespace {

// The spring with the largest share of the mode's strain energy ½·c·(Δv)² (v: the mode's shape).
int mostStrainedSpring(const Eigen::VectorXd& v, const std::vector<double>& c) {
  int best = 0;
  double e_best = -1;
  for (size_t i = 0; i < c.size(); ++i) {
    const double d = v[i + 1] - v[i], energy = 0.5 * c[i] * d * d;
    if (energy > e_best) {
      e_best = energy;
      best = int(i);
    }
  }
  return best;
}

// The chain's elastic modes at one crank angle widen their bands; the spring that names each mode
// is the one it strains most where its frequency is lowest.
void widenBands(CrankshaftChainModes& out, const Eigenpairs& e, const std::vector<double>& c, const Scene& sc,
                const TorsionalChainLayout& chain, bool elastic) {
  const int elastic_modes = int(e.lambda.size()) - 1;
  if (out.modes.empty()) out.modes.resize(elastic_modes, {INFINITY, -INFINITY, 0, 0, ""});
  for (int m = 0; m < elastic_modes; ++m) {
    const double p = std::sqrt(std::max(e.lambda[m + 1], 0.0));
    ChainModeBand& b = out.modes[m];
    if (p < b.p_min) {
      b.p_min = p;
      b.shape = springName(sc, chain, elastic, mostStrainedSpring(e.vectors.col(m + 1), c));
    }
    b.p_max = std::max(b.p_max, p);
  }
}

std::string chainApproximations(const Scene& sc, int angles) {
  return "lumped chain (each throw a rigid rotor, the segments massless springs G·I_p/Δz), frozen at " +
         std::to_string(angles) + " crank angles over a revolution (the carts' reduced inertias held at each), "
         "undamped (coupling damping, motor slope and loads left out)" +
         std::string(sc.hasBacklash() ? ", the reducer's teeth permanently in contact" : "");
}

}  // namespace

CrankshaftChainModes crankshaftChainModes(const Scene& sc, int angles) {
  CrankshaftChainModes out;
  if (!sc.crankshaft.torsionalChain()) {
    out.not_applicable = "the crankshaft is rigid (no crankshaft.torsional_stiffness)";
    return out;
  }
  const TorsionalChainLayout chain = torsionalChainLayout(sc);
  const bool elastic = sc.coupling.type == CouplingType::Elastic;
  for (size_t k = 0; k < chain.stiffness.size(); ++k)
    out.segments.push_back({chain.cart_of_throw[k] + 1, chain.cart_of_throw[k + 1] + 1, chain.length[k], chain.stiffness[k]});
  out.applies = true;
  out.angles = angles;
  std::vector<double> J, c;
  for (int a = 0; a < angles; ++a) {
    const double phi = 2.0 * M_PI * a / angles;
    chainAtAngle(sc, phi, J, c);
    widenBands(out, solveChain(J, c), c, sc, chain, elastic);
  }
  for (ChainModeBand& b : out.modes) {
    b.f_min = b.p_min / (2.0 * M_PI);
    b.f_max = b.p_max / (2.0 * M_PI);
  }
  out.approximations = chainApproximations(sc, angles);
  return out;
}

}  // namespace rollerdyn::modes
