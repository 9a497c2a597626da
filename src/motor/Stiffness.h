// When a motor law makes the equations stiff, and the integrators switch to methods for stiff
// problems (CVODE BDF in the reduced model and in the multibody model's minimal formulation).
//
// The mechanical motion of the papers' machines is integrated with steps of about 1-6 ms at the
// accuracies used (1e-4 ... 1e-8: 10 s of balanced-4cart take ~1600-4500 steps). An implicit
// Adams-Moulton method (and every explicit Runge-Kutta) stays stable on a decaying mode
// λ = -1/τ only for h·|λ| below about 1.8 at order 5 (less at higher orders), so a law whose
// fastest time constant τ is below ~10 ms forces steps set by stability, not accuracy, for the
// whole run: the space-phasor (Park) machine's electrical transients (τ of 1-30 ms, oscillating
// at the supply frequency in the frame of the supply) are of that kind; the dynamic Kloss
// characteristic's electromagnetic time constant T_e = 1/(ω0·s_kr) (≈ 80 ms for the papers'
// 4A200M6U3) is not.
#pragma once

#include "motor/MotorLaw.h"

namespace rollerdyn {

inline constexpr double kStiffTimeConstant = 0.01;  // [s], argued above

// True when `law` (may be null) has dynamics faster than kStiffTimeConstant.
inline bool lawIsStiff(const MotorLaw* law) { return law && law->fastestTimeConstant() < kStiffTimeConstant; }

}  // namespace rollerdyn
