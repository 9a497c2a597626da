#include "physics/GuideFrictionLoop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rollerdyn {
namespace {

// Sign passes before the fixed-point fallback: the first pattern is nearly always right, one flip
// settles the rest; a third or fourth pass only happens where a normal force crosses zero.
constexpr int kMaxSignPasses = 4;
// Fixed-point iterations of the fallback: a contraction of ratio q gains -log10(q) digits per
// iteration, so 60 reach round-off for any q <= 0.5; a slower one is reported, not waited for.
constexpr int kMaxFixedPointPasses = 60;

double sgn(double x) { return x < 0.0 ? -1.0 : 1.0; }

void normalsAt(const GuideLoopCart& c, double eps, double F, double* n) {
  for (int i = 0; i < 2; ++i) n[i] = c.n0[i] + c.n_eps[i] * eps + c.n_F[i] * F;
}

}  // namespace

GuideLoopResult solveGuideFrictionLoop(const GuideLoopCart* carts, int n, double eps0, double* friction,
                                       double* normals) {
  GuideLoopResult r;
  // Signs of the normal forces without friction (stored in `normals` while iterating).
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < 2; ++i) normals[2 * j + i] = sgn(carts[j].n0[i] + carts[j].n_eps[i] * eps0);

  for (int pass = 0; pass < kMaxSignPasses; ++pass) {
    ++r.passes;
    double numerator = eps0, E = 1.0;
    for (int j = 0; j < n; ++j) {
      const GuideLoopCart& c = carts[j];
      const double s0 = normals[2 * j], s1 = normals[2 * j + 1];
      const double gain = c.c * (s0 * c.n_F[0] + s1 * c.n_F[1]);
      if (c.c != 0.0 && !(1.0 - gain > 0.0)) {
        r.status = LoopStatus::SelfLocking;
        r.cart = j;
        r.gain = gain;
        return r;
      }
      const double D = 1.0 - gain;
      const double alpha = c.c * (s0 * c.n0[0] + s1 * c.n0[1]) / D;
      const double beta = c.c * (s0 * c.n_eps[0] + s1 * c.n_eps[1]) / D;
      friction[j] = alpha;  // F_j = α_j + β_j·ε, ε still unknown: keep α, β
      numerator += c.w * alpha;
      E -= c.w * beta;
      // β is recomputed below from the same numbers (no scratch storage).
    }
    if (!(E > 0.0)) {
      r.status = LoopStatus::Undetermined;
      r.gain = 1.0 - E;
      return r;
    }
    const double eps = numerator / E;
    bool consistent = true;
    for (int j = 0; j < n; ++j) {
      const GuideLoopCart& c = carts[j];
      const double s0 = normals[2 * j], s1 = normals[2 * j + 1];
      const double D = 1.0 - c.c * (s0 * c.n_F[0] + s1 * c.n_F[1]);
      const double beta = c.c * (s0 * c.n_eps[0] + s1 * c.n_eps[1]) / D;
      friction[j] += beta * eps;
      double N[2];
      normalsAt(c, eps, friction[j], N);
      // A normal force of the wrong sign, beyond round-off of its own terms, flips its sign.
      for (int i = 0; i < 2; ++i) {
        const double scale = std::abs(c.n0[i]) + std::abs(c.n_eps[i] * eps) + std::abs(c.n_F[i] * friction[j]);
        if (N[i] * normals[2 * j + i] < 0.0 && std::abs(N[i]) > 1e-12 * scale) {
          normals[2 * j + i] = -normals[2 * j + i];
          consistent = false;
        }
      }
    }
    if (consistent) {
      r.eps = eps;
      for (int j = 0; j < n; ++j) normalsAt(carts[j], eps, friction[j], normals + 2 * j);
      return r;
    }
  }

  // Fallback: F <- c·|N(F)| from the last pass's friction.
  double eps = eps0;
  for (int j = 0; j < n; ++j) eps += carts[j].w * friction[j];
  for (int it = 0; it < kMaxFixedPointPasses; ++it) {
    ++r.passes;
    double change = 0.0, size = 0.0, eps_next = eps0;
    for (int j = 0; j < n; ++j) {
      double N[2];
      normalsAt(carts[j], eps, friction[j], N);
      const double F = carts[j].c * (std::abs(N[0]) + std::abs(N[1]));
      change = std::max(change, std::abs(F - friction[j]));
      size = std::max(size, std::abs(F));
      friction[j] = F;
      eps_next += carts[j].w * F;
    }
    eps = eps_next;
    if (change <= 1e-13 * size || size == 0.0) {
      r.eps = eps;
      for (int j = 0; j < n; ++j) normalsAt(carts[j], eps, friction[j], normals + 2 * j);
      return r;
    }
  }
  r.status = LoopStatus::NotSettled;
  return r;
}

std::string describeLoopFailure(const GuideLoopResult& r) {
  char buf[400];
  switch (r.status) {
    case LoopStatus::Solved: return "solved";
    case LoopStatus::SelfLocking:
      std::snprintf(buf, sizeof buf,
                    "guide friction locks cart %d in its guides (self-locking: its friction grows with the rod "
                    "force that causes it at a gain of %.3g >= 1, so no rod force moves it)",
                    r.cart + 1, r.gain);
      return buf;
    case LoopStatus::Undetermined:
      std::snprintf(buf, sizeof buf,
                    "guide friction makes the machine's effective inertia non-positive (the friction's feedback "
                    "on the crank acceleration has gain %.3g >= 1): the motion is undetermined (Painlevé's "
                    "paradox of friction)",
                    r.gain);
      return buf;
    case LoopStatus::NotSettled:
      return "the guide friction and the guide normal forces found no consistent solution (the loop does not "
             "contract: friction coefficient too large for these cart positions)";
  }
  return "?";
}

}  // namespace rollerdyn
