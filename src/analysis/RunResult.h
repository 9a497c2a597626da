// What one simulation run produces, whichever model ran it (MuJoCo's "data" after the run).
// Both models fill the same column names so that analysis, writers and `compare` never need to
// know which model produced a table. The columns of the time series and the reactions (name, unit,
// meaning, sign convention, which model writes each and when) are defined once, in the output
// column table io/OutputColumns.h, which docs/outputs.md renders; SI units, angles in rad.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "analysis/CrankSpeedExtrema.h"
#include "io/Table.h"

namespace rollerdyn {

// Energy book-keeping over the run [J]; every work term is integrated alongside the equations
// of motion (not summed from output samples), so the residual measures integration error.
struct EnergyAudit {
  double motor_work = 0;          // ∫ M_motor·ω_motor dt, input by the motor
  double damping_dissipation = 0; // ∫ k·(Δω)² dt ≥ 0, lost in the coupling damper
  double friction_dissipation = 0;// ∫ -F_friction·v dt, lost in the guides (≥ 0 when friction opposes v)
  double load_work = 0;           // ∫ -F_load·v dt: work the machine does on the concrete
  double brake_dissipation = 0;   // ∫ -M_brake·ω_motor dt ≥ 0, lost in the brake (motor.stop.brake_torque)
  // ∫ L·ω_motor dt: lost in the reducer on the motor's torque (reducer.losses, physics/
  // ReducerLosses.h): ≥ 0 by the direction of the power flow; under the papers' constant η
  // (1/η − 1)·motor_work, negative while the crank side drives. motor_work is what the motor
  // puts into the mechanism after the reducer, so the motor's work at its shaft is the sum:
  double reducer_losses = 0;
  double motorShaftWork() const { return motor_work + reducer_losses; }
  double kinetic_initial = 0, kinetic_final = 0;
  double potential_initial = 0, potential_final = 0;  // gravity + coupling spring

  // motor work (after the reducer) - dissipation - load work - ΔT - ΔV; with the reducer's
  // column: motor shaft work - reducer losses - dissipation - load work - ΔT - ΔV, the same sum
  double residual() const {
    return motor_work - damping_dissipation - friction_dissipation - load_work - brake_dissipation -
           (kinetic_final - kinetic_initial) - (potential_final - potential_initial);
  }
  // residual divided by the largest energy flow term (motor work, or the kinetic energy when
  // the motor is off), so it stays meaningful for a free-running machine.
  double residualRelative() const;
};

// One reaction column of the multibody minimal formulation's self-check: its O(n) value against
// Simbody's constrained solve over the checked rows.
struct ReactionCheck {
  std::string column;          // reactions.csv column, e.g. "N_front_2", "bearing_x"
  double max_difference = 0;   // largest |O(n) value - Simbody's| over the checked rows [N, N·m]
  double max_value = 0;        // largest |Simbody's value| there [N, N·m]
};

struct RunStats {
  long steps = 0;                  // accepted integrator steps
  long realizations = 0;           // right-hand-side evaluations (Dynamics-stage realizations)
  long error_test_failures = -1;   // steps the integrator's error test rejected and retried
                                   // smaller; -1: not counted (Baranov's fixed-step scheme)
  long jacobian_evaluations = -1;  // Newton iteration-matrix Jacobians formed; -1: not counted
  long newton_convergence_failures = -1;  // corrector convergence failures (each retries the step
                                          // smaller); -1: not counted
  double cpu_seconds = 0;          // process CPU time of the integration
  double constraint_error_max = 0; // max over output rows of the constraint error norm [-]
  bool complete = true;            // false when the run ended before t_end
  double formulation_self_check = -1;  // multibody minimal formulation: max relative difference of its
                                       // accelerations and guide normal forces from Simbody's
                                       // constrained solve [-]; -1: not run
  long self_check_rows = 0;            // output rows checked against Simbody's constrained solve
  std::vector<ReactionCheck> reaction_self_check;  // per reaction column (empty: none checked)
  std::string status = "completed";  // e.g. "completed", "motor stalled at t = 3.2 s"
};

struct RunResult {
  std::string model;               // "multibody" | "reduced"
  std::string integrator;          // integrator actually used
  Table timeseries;
  Table reactions;
  // Every local extremum of omega_crank inside the integrator's steps (CrankSpeedExtrema.h), in
  // time order: the extremes of δ and of the steady-state test, which output rows alone miss.
  std::vector<CrankSpeedExtremum> crank_speed_extrema;
  RunStats stats;
  EnergyAudit energy;
  std::vector<std::string> effects;  // effects built (Scene::effects), e.g. "kloss_motor", "elastic_coupling"
  // Normal force of the guide friction (and of the reduced model's reactions), in words for the
  // user: e.g. "algebraic (guide reaction of the same instant)"; empty without guide friction
  // in a model that has no reactions of its own to describe.
  std::string guide_normals;
  // Reduced model with the papers' quasi-static normals: the friction work the same run would
  // have done with kinetostatic normals at its own accelerations [J]; NaN where not computed.
  double friction_work_kinetostatic = std::numeric_limits<double>::quiet_NaN();
};

// Helpers of the run loops that fill a RunResult.
// True when every value of an output row is finite (a NaN or inf ends a run as a numerical failure).
bool rowIsFinite(const std::vector<double>& row);
// A status line naming the time of an event, e.g. "integration failed at t = 3.125 s" (4 digits).
std::string statusAt(const char* what, double t);

}  // namespace rollerdyn
