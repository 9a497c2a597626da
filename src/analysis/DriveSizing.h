// The answers a drive is sized with, computed once from a RunResult (so the multibody and the
// reduced model get the same figures from the same columns) over two windows: the steady-state
// window (SteadyState.h) and the whole run (start-up from the initial state, the steady running,
// and whatever else the run holds). Motor torques, powers and slip against the motor's nominal and
// breakdown torque, the flywheel that would bring the coefficient of unevenness δ to a target, the
// coupling torque against its rating, and the bearing loads and lives of every joint (JointSizing.h).
//
// The checks (SizingCheck) each name the window that decided them:
//  * motor heating: the larger of RMS/M_n over the steady window and the thermal equivalent of the
//    whole run. Heat in an induction motor's rotor is s·P_ag = s·M·ω0 exactly (slip times air-gap
//    power), and at nominal load s_n·M_n·ω0; on the running branch s ≈ s_n·M/M_n, so the mean of
//    s·M over (s_n·M_n) is (RMS/M_n)², the usual RMS rule. At start-up (s near 1) the same
//    losses are tens of times the running ones, which the RMS of the torque cannot show; the
//    start's heat counts them: the start-up answers' rotor energy loss (StartUp.h, one
//    computation), of which a start adds what exceeds the steady losses over its duration. How often a start comes
//    is the duty's, not the run's (a 10 s run is not a start every 10 s): with
//    sizing.starts_per_hour the equivalent is √((steady s·M + starts per hour × start heat)/(s_n·M_n));
//    without it the drive runs continuously, the steady window decides, and the check reports
//    the starts per hour the rotor's heat allows (fails below one). Stator and iron losses are
//    taken to scale like the rotor's (they follow the current, which follows √(s·M) off nominal).
//  * breakdown margin: peak |M| / M_kr over the steady window only, below 0.95² = 0.9025 (the
//    breakdown torque goes with the square of the voltage, and IEC 60034-1 zone A allows the
//    supply 5 % low): a start from rest passes through M_kr by design (the static law reaches
//    exactly M_kr at s_kr), so the whole run always reads 1 there; a steady peak near M_kr means
//    the motor falls off its running branch at the first dip of the supply.
//  * coupling: peak |M| / rating over the whole run (start-up peaks included) and the steady
//    window; the larger decides.
// A drive that does not turn (stalled, rocking) fails the motor checks with the reason, and the
// other checks do not apply: the loads of a working drive are unknown.

//
// Notation: u reducer ratio, η reducer efficiency, ω0 synchronous rotor speed, ω_r rotor speed,
// M motor torque at the rotor shaft, M·u·η the same at the crank (the `motor_torque` column),
// s = 1 - ω_r/ω0 slip, M_kr breakdown torque, M_n nominal torque, λ = M_kr/M_n.
#pragma once

#include <string>
#include <vector>

#include "analysis/CouplingSelection.h"
#include "analysis/Fatigue.h"
#include "analysis/GearDuty.h"
#include "analysis/MotorDuty.h"
#include "analysis/CrankshaftBearings.h"
#include "analysis/JointSizing.h"
#include "analysis/RunResult.h"
#include "analysis/SizingCheck.h"
#include "analysis/StartUp.h"
#include "analysis/SteadyState.h"
#include "scene/Scene.h"

namespace rollerdyn {

// Every double is NaN when it cannot be computed (column absent, no motor, nothing given).
// Motor figures over the whole run (NaN when not computable).
struct MotorWholeRun {
  double torque_shaft_mean = 0, torque_shaft_rms = 0, torque_shaft_peak = 0;  // M at the rotor [N·m]
  double rms_over_nominal = 0;     // RMS / M_n [-]
  double rotor_losses_mean = 0;    // mean of s·M·ω0, the rotor's copper losses [W]
  double thermal_over_nominal = 0; // duty thermal equivalent √((steady s·M + starts/h × start heat/3600 s)
                                   // /(s_n·M_n)) [-]; NaN without a duty (continuous running);
                                   // RMS/M_n over the whole run when s_n is not known
  std::string thermal_basis;       // which of the two
  bool continuous_running = false; // the heating check reads the steady window (no duty given, s_n known)
  double start_heat = 0;           // the start's rotor heat: the start-up answers' rotor energy loss
                                   // (StartUp.h, ∫M·(ω0·f/f_n − ω_r) dt from the switch-on to the
                                   // steady window while connected; the same number) [J]
  double start_duration = 0;       // that start, switch-on to the steady window [s]
  double start_heat_above_steady = 0;  // what a start adds to steady running: start_heat minus the
                                       // steady window's mean losses × start_duration [J]
  double duty_starts_per_hour = 0; // starts per hour of the duty (sizing.starts_per_hour; 0: continuous) [1/h]
  double steady_rotor_losses = 0;  // mean of s·M·ω0 over the steady window [W]; NaN: not known
  double nominal_rotor_losses = 0; // s_n·M_n·ω0 [W]; NaN: s_n or M_n not known
  double starts_per_hour = 0;      // starts per hour the rotor's heat balance allows at this load:
                                   // 3600·(s_n·M_n·ω0 − steady losses)/start_heat_above_steady [1/h]
  double power_line_mean = 0, power_line_peak = 0;  // drawn from the line [W]
  double slip_min = 0, slip_max = 0;  // s [-]
};

struct MotorSizing {
  bool available = false;          // motor on and the run has motor_torque and omega_motor
  double torque_shaft_mean = 0, torque_shaft_rms = 0, torque_shaft_peak = 0;  // M at the rotor [N·m]
  double torque_crank_mean = 0, torque_crank_rms = 0, torque_crank_peak = 0;  // M·u·η at the crank [N·m]
  double nominal_torque = 0;       // M_n at the rotor [N·m]
  std::string nominal_source;      // where M_n comes from (scene key or the Kloss data)
  double breakdown_torque = 0;     // M_kr at the rotor [N·m]
  double breakdown_torque_generating = 0;  // the fitted law's braking pull-out torque above synchronous
                                           // speed (Kloss: M_kr, symmetric); reported, not checked [N·m]
  double rms_over_nominal = 0;     // thermal check: RMS torque / M_n [-], passes when ≤ 1
  double torque_motoring_peak = 0, torque_generating_peak = 0;  // max M and max -M in the window (≥ 0) [N·m]
  double peak_over_breakdown = 0;  // max(motoring peak, braking peak) / M_kr [-], passes when < 0.9025
  double power_shaft_mean = 0, power_shaft_peak = 0;  // M·ω_r: mean and max [W]
  double power_line_mean = 0, power_line_peak = 0;    // drawn from the line [W]
  std::string line_power_basis;    // the efficiency assumption behind the line power
  double breakdown_torque_catalogue = 0;  // the catalogue's (M_k/M_n)·P_n/ω_n beside a Kloss law's
                                          // M_kr, the one the checks use; NaN under a law fitted to
                                          // the catalogue or without one [N·m]
  std::string data_conflict;       // the Kloss data against the same motor's catalogue, when they
                                   // disagree beyond 10 % (the motor checks say so); "" otherwise
  double slip_min = 0, slip_max = 0;  // s over the window [-]
  double energy_per_revolution = 0;   // ∫ M·ω_r dt per crank revolution [J]; NaN unless turning
  MotorWholeRun whole_run;            // the same over the whole run
};

struct FlywheelSizing {
  double kinetic_energy_swing = 0;  // ΔT, largest max - min of the machine's kinetic energy over
                                    // one steady crank revolution [J]
  double inertia_effective = 0;     // J, time mean of 2T/ω_crank² over the window [kg·m²] (crank axis)
  double delta = 0;                 // δ of the run [-]
  double target_delta = 0;          // the target δ* [-]; NaN when not given
  double excess_work = 0;           // ΔA of a revolution at constant speed (StartLoad) [J]; NaN: not known
  double omega_mean = 0;            // mean crank speed of the window [rad/s]
  double inertia_required = 0;      // J* = ΔA/(δ*·ω̄²), the drive inertia at the crank for δ* [kg·m²]
  double added_inertia_energy_method = 0;  // J·(δ/δ* - 1): the run's δ·J held constant [kg·m²]
  std::string method;               // which of the two gave added_inertia_crank, in words
  bool estimate = false;            // a flywheel is proposed, by estimate (simulate never runs it)
  std::string basis;                // what the proposal rests on: an estimate (not run) and its accuracy, or
                                    // the run's own δ meeting δ*; "" without a proposal
  double added_inertia_crank = 0;   // ΔJ ≥ 0 on the crankshaft: J* - J, or without ΔA J·(δ/δ* - 1) [kg·m²]
  double flywheel_crankshaft = 0;   // flywheel on the crankshaft reaching δ* (present + ΔJ) [kg·m²]
  double flywheel_motor_shaft = 0;  // the same on the motor shaft: ΔJ/(δ_red·u²) + present [kg·m²]
};

struct CouplingSizing {
  bool available = false;          // the run has a coupling_torque column
  double mean = 0, peak = 0, swing = 0;  // coupling torque at the crank axis: mean, max |M|, max - min [N·m]
  double rating = 0;               // sizing.coupling_rated_torque [N·m]; NaN when not given
  double peak_over_rating = 0;     // [-], passes when ≤ 1
  double peak_whole_run = 0, t_peak_whole_run = 0;  // max |M| over the whole run and when [N·m], [s]
  double peak_over_rating_whole_run = 0;            // [-]
};

struct DriveSizing {
  double t_begin = 0, t_end = 0;  // steady window [s]
  double run_t_begin = 0, run_t_end = 0;  // whole run: the finite rows [s]
  std::string motion;             // the crank's motion (RunMotion.h)
  std::string stall_cause;        // why a drive that does not turn fails: the start-up answers' one
                                  // sentence (StartUp::stall_cause); "" when not known
  bool steady_reached = false;    // the run reached a steady state (SteadyState::reached): the checks
                                  // that read the steady window apply only then
  std::string steady_not_reached; // SteadyState::not_reached: why not and how long to run; "" when reached
  // The start from rest, from the start-up answers (StartUp.h): whether this run simulates one
  // (switched on at rest within the run), whether and how the drive starts.
  bool start_simulated = false;   // the run starts the machine from rest
  int can_start_from_rest = -1;   // StartUp::can_start_from_rest: 1 yes, 0 no, -1 not known
  std::string start_verdict;      // StartUp::verdict
  double start_load_ratio = 0;    // the larger of load at the start angle / starting torque and mean
                                  // load / largest torque, both under the supply the starting method
                                  // holds at standstill (StartUp.h) [-]: < 1 lets the motor start;
                                  // NaN when the loads are not known
  double revolutions = 0;         // crank revolutions in the window [-]
  MotorSizing motor;
  FlywheelSizing flywheel;
  CouplingSizing coupling;
  std::vector<JointSizing> joints;  // per cart: guide rollers, rod end, crank pin; then main bearing
  FatigueSizing fatigue;          // damage per start and per hour (Fatigue.h)
  CouplingSelection coupling_selection;  // the manufacturers' coupling checks (CouplingSelection.h)
  GearDuty gear;                  // the reducer's load spectrum and K_A after ISO 6336-6 (GearDuty.h)
  MotorDuty motor_duty;           // the motor's starts after IEC 60034-1, duty S1 / S4 (MotorDuty.h)
  CrankshaftSizing crankshaft;      // bending moments at the throws, torques of the shaft segments
                                    // (crankshaft.throw_positions; CrankshaftBearings.h)
  std::vector<SizingCheck> checks;  // start, motor_heating, motor_breakdown, coupling
  // The most loaded joint of each kind (largest P, else largest peak); nullptr when none.
  const JointSizing* worst(const std::string& joint) const;
};

// Nominal motor torque M_n at the rotor [N·m]: sizing.motor_nominal_torque, else
// sizing.motor_nominal_power/ω_n, else M_kr/λ from the Kloss data (motor.omega_nominal and
// motor.overload_ratio); NaN when none is given. `source` receives which, in words.
double nominalMotorTorque(const Scene& scene, std::string* source = nullptr);

// `turning`: whether the crank turns in the window (per-revolution figures are NaN otherwise);
// `delta`: the run's coefficient of unevenness (Metrics.h); `motion`: the crank's motion in words
// (RunMotion.h; "" = "turning" or "not turning" from `turning`), named by a failed check;
// `start_up`: the run's start-up answers (StartUp.h), whose rotor energy loss is the start's heat
// in the heating check (null: no start-up answers, the start's heat is not known). Without the
// argument they are computed here with the scene's motor law.
DriveSizing computeDriveSizing(const Scene& scene, const RunResult& run, const SteadyState& window,
                               bool turning, double delta, const std::string& motion = "");
// `load`: the load torques and the excess work of a revolution (StartLoad, RunMotion.h); with its
// excess work the flywheel for δ* is ΔA/(δ*·ω̄²) less the drive's present inertia, else (null or
// NaN) the run's δ·J extrapolated.
DriveSizing computeDriveSizing(const Scene& scene, const RunResult& run, const SteadyState& window,
                               bool turning, double delta, const std::string& motion, const StartUp* start_up,
                               const StartLoad* load = nullptr);

// Power drawn from the line for a motor torque M at the rotor [W]: the air-gap power M·ω0 (what
// crosses to the rotor: shaft power plus the rotor's copper losses s·M·ω0), times (1 - s_n)/η_m
// for the stator and iron losses as at the nominal point (η_m = sizing.motor_efficiency; there
// the formula gives P_n/η_m), divided by it when generating. Without η_m: the air-gap power.
// A locked rotor thus draws its full air-gap power as heat, never "no power".
double linePower(double M, double omega_sync, double slip_nominal, double motor_efficiency);

// The machine's kinetic energy at each timeseries row [J], rigid-body parts at the crank axis:
//   T = ½J_n1·ω_motor² + ½J_c·ω_crank² + Σ_j ½(m'_B + m_rod/2)·v_j² + n·½(m_rod/2)·r²·ω_crank²,
// the rod counted half at the cart and half at the crank pin (Loveikin, Pochka, Romasevych (2018)
// eq. (2)-(3)); exact for split rods, within the rod's own rotation for distributed ones.
std::vector<double> kineticEnergy(const Scene& scene, const Table& timeseries);

}  // namespace rollerdyn
