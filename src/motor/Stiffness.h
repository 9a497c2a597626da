// When a motor law makes the equations stiff, and the integrators switch to methods for stiff
// problems (CVODE BDF in the reduced model and in the multibody model's minimal formulation;
// Adams-Moulton otherwise, as without a motor law).
//
// CVODE's Adams-Moulton (orders ≤ 5 here) stays stable on a decaying mode λ = -1/τ only for
// h·|λ| below about 1.8; BDF has no such bound on the real axis (orders 1-2 none at all). A law
// whose fastest time constant τ is well below the steps the mechanics take therefore holds Adams
// to steps set by stability. The space-phasor (Park) machine's electrical modes have τ of about
// 1-5 ms for real motors (4A200M6U3 fitted to its catalogue: 1.6 ms; Krause's 3 hp machine:
// 3.2 ms), while the papers' machines step 1-3 ms at accuracies 1e-5 ... 1e-7. Measured (crank
// speed error over the run against accuracy 1e-11, work in steps; balanced-4cart, 3 s direct-on-
// line start; energy-balanced-3cart, 15 s):
//   τ = 1.6 ms: Adams on the same work-precision line as BDF or better (reduced 1214 steps for
//     2.0e-6 against BDF 1118 for 9.7e-6; minimal 2476 for 1.0e-7 against 3108 for 2.7e-7;
//     energy-balanced-3cart minimal 13625 for 1.2e-6 against 15985 for 1.8e-6);
//   τ = 0.16 ms (the same machine with leakages ÷10): BDF ahead (reduced 2169 steps for 3.5e-4
//     against Adams 4349 for 1.1e-4 and 5826 for 1.7e-5 ... BDF 2987 for 5.1e-5; minimal 5045
//     for 7.3e-6 against Adams 6117 for 1.7e-5).
// So the switch sits between: below 0.5 ms the law is stiff. The dynamic Kloss characteristic
// (T_e = 1/(2π·f_n·s_kr) ≈ 28 ms for the papers' 4A200M6U3) never is.
#pragma once

#include "motor/MotorLaw.h"

namespace rollerdyn {

inline constexpr double kStiffTimeConstant = 0.5e-3;  // [s], argued above

// True when `law` (may be null) has dynamics faster than kStiffTimeConstant.
inline bool lawIsStiff(const MotorLaw* law) { return law && law->fastestTimeConstant() < kStiffTimeConstant; }

}  // namespace rollerdyn
