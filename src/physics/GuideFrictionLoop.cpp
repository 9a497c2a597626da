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

// The loop's data: the carts, the crank acceleration without friction, and the caller's arrays
// the solution goes to (`normals` holds the sign pattern while the sign passes run).
struct GuideLoop {
  const GuideLoopCart* carts;
  int n;
  double eps0;
  double* friction;
  double* normals;
};

// c·(s_front·v_front + s_rear·v_rear): the cart's friction per unit of v under the signs s.
double signedShare(const GuideLoopCart& c, const double* s, const double* v) {
  return c.c * (s[0] * v[0] + s[1] * v[1]);
}

// The solution found: ε, and every normal force at it.
void settle(const GuideLoop& loop, double eps, GuideLoopResult& r) {
  r.eps = eps;
  for (int j = 0; j < loop.n; ++j) normalsAt(loop.carts[j], eps, loop.friction[j], loop.normals + 2 * j);
}

// Whether cart j locks in its guides: with friction, its friction per unit of its own friction
// under the signs, `gain`, reaches 1 (or is not a number), so the friction feeds itself. Says so in r.
bool locksInGuides(const GuideLoopCart& c, double gain, int j, GuideLoopResult& r) {
  if (c.c == 0.0 || 1.0 - gain > 0.0) return false;
  r.status = LoopStatus::SelfLocking;
  r.cart = j;
  r.gain = gain;
  return true;
}

// The equation in ε for the current sign pattern: α_j into friction[j], the solution into eps.
// False, with the status in r, when a cart locks in its guides or the effective inertia is
// non-positive.
bool solveEquationInEps(const GuideLoop& loop, double& eps, GuideLoopResult& r) {
  double numerator = loop.eps0, E = 1.0;
  for (int j = 0; j < loop.n; ++j) {
    const GuideLoopCart& c = loop.carts[j];
    const double* s = loop.normals + 2 * j;
    const double gain = signedShare(c, s, c.n_F);
    if (locksInGuides(c, gain, j, r)) return false;
    const double D = 1.0 - gain;
    const double alpha = signedShare(c, s, c.n0) / D;
    const double beta = signedShare(c, s, c.n_eps) / D;
    loop.friction[j] = alpha;  // F_j = α_j + β_j·ε, ε still unknown: keep α, β
    numerator += c.w * alpha;
    E -= c.w * beta;
  }
  if (!(E > 0.0)) {
    r.status = LoopStatus::Undetermined;
    r.gain = 1.0 - E;
    return false;
  }
  eps = numerator / E;
  return true;
}

// F_j = α_j + β_j·ε, and the normal forces at it: a normal force of the wrong sign, beyond
// round-off of its own terms, flips its sign. True when no sign flipped.
bool signsConsistent(const GuideLoop& loop, double eps) {
  bool consistent = true;
  for (int j = 0; j < loop.n; ++j) {
    const GuideLoopCart& c = loop.carts[j];
    double* s = loop.normals + 2 * j;
    // β recomputed from the same numbers as in the equation in ε (no scratch storage).
    const double D = 1.0 - signedShare(c, s, c.n_F);
    const double beta = signedShare(c, s, c.n_eps) / D;
    loop.friction[j] += beta * eps;
    double N[2];
    normalsAt(c, eps, loop.friction[j], N);
    for (int i = 0; i < 2; ++i) {
      const double scale = std::abs(c.n0[i]) + std::abs(c.n_eps[i] * eps) + std::abs(c.n_F[i] * loop.friction[j]);
      if (N[i] * s[i] < 0.0 && std::abs(N[i]) > 1e-12 * scale) {
        s[i] = -s[i];
        consistent = false;
      }
    }
  }
  return consistent;
}

// Fallback: F <- c·|N(F)| from the last pass's friction, until it stops changing. False when it
// does not within kMaxFixedPointPasses.
bool fixedPointFallback(const GuideLoop& loop, GuideLoopResult& r) {
  double eps = loop.eps0;
  for (int j = 0; j < loop.n; ++j) eps += loop.carts[j].w * loop.friction[j];
  for (int it = 0; it < kMaxFixedPointPasses; ++it) {
    ++r.passes;
    double change = 0.0, size = 0.0, eps_next = loop.eps0;
    for (int j = 0; j < loop.n; ++j) {
      double N[2];
      normalsAt(loop.carts[j], eps, loop.friction[j], N);
      const double F = loop.carts[j].c * (std::abs(N[0]) + std::abs(N[1]));
      change = std::max(change, std::abs(F - loop.friction[j]));
      size = std::max(size, std::abs(F));
      loop.friction[j] = F;
      eps_next += loop.carts[j].w * F;
    }
    eps = eps_next;
    if (change <= 1e-13 * size || size == 0.0) {
      settle(loop, eps, r);
      return true;
    }
  }
  return false;
}

}  // namespace

GuideLoopResult solveGuideFrictionLoop(const GuideLoopCart* carts, int n, double eps0, double* friction,
                                       double* normals) {
  const GuideLoop loop{carts, n, eps0, friction, normals};
  GuideLoopResult r;
  // Signs of the normal forces without friction (stored in `normals` while iterating).
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < 2; ++i) normals[2 * j + i] = sgn(carts[j].n0[i] + carts[j].n_eps[i] * eps0);

  for (int pass = 0; pass < kMaxSignPasses; ++pass) {
    ++r.passes;
    double eps = 0.0;
    if (!solveEquationInEps(loop, eps, r)) return r;
    if (signsConsistent(loop, eps)) {
      settle(loop, eps, r);
      return r;
    }
  }
  if (!fixedPointFallback(loop, r)) r.status = LoopStatus::NotSettled;
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
