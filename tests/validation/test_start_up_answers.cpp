// The start-up answers (analysis/StartUp.h) on runs of both models:
//  * the rotor energy loss of a start without load is the classical J·ω0²/2 (J the inertia at
//    the rotor): for a rigid drive ∫M dt = J·ω_end and ∫M·ω_r dt = J·ω_end²/2, so the slip
//    power ∫M·(ω0 - ω_r) dt = J·(ω0·ω_end - ω_end²/2) -> J·ω0²/2 as ω_end -> ω0, whatever the
//    motor law. Tolerance 2e-4 relative: the slip at the end is ~e^-60 (Kloss's time constant
//    near synchronous speed J·ω0·s_kr/(2·M_kr) ≈ 15 ms, against ~2 s of running), the cart
//    inertia varies the drive's J by ~1e-7, and the trapezoidal rule on 1 ms output rows errs by
//    about h²/12·|f''|/|f| ~ 1e-5 for an integrand that changes on the run-up's ~0.1 s scale;
//  * a switch-off gives a stopping time and a run-out, shorter with a brake;
//  * a start the motor cannot make is named, with the torques that explain it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "analysis/StartUp.h"
#include "analysis/SizingSummary.h"
#include "analysis/StartUpSummary.h"
#include "analysis/Summary.h"
#include "motor/BreakdownTorque.h"
#include "motor/MotorLawFactory.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "studies/StartLoad.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn {
namespace {

// The papers' motor on a crankshaft of 50 kg·m² with (almost) massless carts, no loads, no
// gravity, a rigid coupling and η = 1: a pure inertia J = (J_p + J_m + J_red) + 50/u² at the rotor.
Scene noLoadScene(MotorModel model) {
  Scene s = test_scenes::loveikin2018Scene();
  s.name = "no-load-start";
  s.carts.mass = 1e-6;
  s.rods = {RodModel::Massless, 0.8, 0.0, 0.0};
  s.crank.shaft_inertia = 50.0;
  s.crank.inertia_per_crank = 0.0;
  s.loads = {0, 0, 0, 0, RollerForceDirection::AsPrinted, 0.0, 0.0, 1e-3};
  s.coupling.type = CouplingType::Rigid;
  s.reducer.efficiency = 1.0;
  s.simulation.t_end = 5.0;
  s.simulation.output_step = 1e-3;
  s.simulation.accuracy = 1e-8;
  s.simulation.formulation = Formulation::Minimal;
  s.induction.model = model;
  return s;
}

TEST(StartUpAnswers, RotorLossOfANoLoadStartIsHalfJOmega0Squared) {
  for (MotorModel model : {MotorModel::Kloss, MotorModel::KlossDynamic}) {
    const Scene s = noLoadScene(model);
    const double u = s.reducer.ratio;
    const double J = s.motor.rotor_inertia + s.coupling.inertia + s.reducer.inertia + s.crank.shaft_inertia / (u * u);
    const double expected = 0.5 * J * s.motor.omega_sync * s.motor.omega_sync;
    const std::unique_ptr<MotorLaw> law = makeMotorLaw(s);
    for (const RunResult& run : {runMultibodyModel(s), runReducedModel(s)}) {
      ASSERT_TRUE(run.stats.complete) << run.stats.status;
      const StartUp a = computeStartUp(s, run, law.get(), nullptr);
      ASSERT_TRUE(a.applicable);
      EXPECT_TRUE(a.starts) << a.verdict;
      std::printf("  %-9s %-13s rotor loss %.6g J, J·ω0²/2 = %.6g J, relative difference %.2g\n", run.model.c_str(),
                  toString(model), a.rotor_energy_loss, expected, a.rotor_energy_loss / expected - 1);
      EXPECT_NEAR(a.rotor_energy_loss, expected, 2e-4 * expected) << run.model << " " << toString(model);
    }
  }
}

TEST(StartUpAnswers, SwitchOffGivesStoppingTimeAndRunOutShorterWithABrake) {
  Scene s = noLoadScene(MotorModel::Kloss);
  s.loads.guide_friction = 0.0;
  s.simulation.output_step = 5e-3;
  s.motor_stop.t_off = 3.0;
  s.simulation.t_end = 12.0;
  // Without loads the machine would coast for ever: a light roller resistance stops it.
  s.carts.mass = 100.0;
  s.loads.roller_force_front = s.loads.roller_force_rear = 300.0;
  s.loads.roller_force_direction = RollerForceDirection::OpposesVelocity;
  const std::unique_ptr<MotorLaw> law = makeMotorLaw(s);
  const StartUp coast = computeStartUp(s, runReducedModel(s), law.get(), nullptr);
  s.motor_stop.brake_torque = 100.0;
  const RunResult braked_run = runReducedModel(s);
  const StartUp braked = computeStartUp(s, braked_run, law.get(), nullptr);
  std::printf("  coast-down: %.3g s, %.3g rev, carts %.3g m; with a 100 N·m brake: %.3g s, %.3g rev, %.3g m\n",
              coast.stopping_time, coast.run_out_revolutions, coast.run_out_cart_path, braked.stopping_time,
              braked.run_out_revolutions, braked.run_out_cart_path);
  ASSERT_TRUE(std::isfinite(coast.stopping_time));
  ASSERT_TRUE(std::isfinite(braked.stopping_time));
  EXPECT_LT(braked.stopping_time, coast.stopping_time);
  EXPECT_LT(braked.run_out_revolutions, coast.run_out_revolutions);
  EXPECT_GT(braked.run_out_cart_path, 0.0);
  // The brake's work is in the energy audit, which still closes.
  EXPECT_GT(braked_run.energy.brake_dissipation, 0.0);
  EXPECT_LT(std::abs(braked_run.energy.residualRelative()), 1e-4);
}

TEST(StartUpAnswers, AStartInStarTheMotorCannotMakeIsExplained) {
  // The paper's drive with loads opposing the velocity (~6.4 kN·m at the start angle, StartLoad)
  // in star: a third of Kloss's starting torque, ≈ 344 N·m at the crank.
  const Scene s = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml",
                                 {"loads.roller_force_direction=opposes_velocity", "motor.start.method=star_delta",
                                  "motor.start.changeover_speed=80", "simulation.t_end=1.5"});
  const StartLoad load = startLoadOf(s);
  const std::unique_ptr<MotorLaw> law = makeMotorLaw(s);
  const StartUp a = computeStartUp(s, runReducedModel(s), law.get(), &load);
  EXPECT_FALSE(a.starts);
  EXPECT_NEAR(a.starting_torque_crank, a.starting_torque_rated_crank / 3.0, 1e-9 * a.starting_torque_crank);
  EXPECT_NE(a.verdict.find("does not start"), std::string::npos) << a.verdict;
  EXPECT_NE(a.verdict.find("star-delta"), std::string::npos) << a.verdict;
  EXPECT_NE(a.verdict.find("below the load torque"), std::string::npos) << a.verdict;
}

// The default scene keeps the papers' static Kloss law: its start-up answers must say plainly
// what that law cannot show and point to the catalogue model, in summary.json and on the console.
TEST(StartUpAnswers, TheDefaultSceneSaysWhatKlossCannotShow) {
  const Scene s = parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml");
  const StartLoad load = startLoadOf(s);
  const nlohmann::json summary = makeSummary(s, runReducedModel(s), &load);
  const nlohmann::json& su = summary["start_up"];
  ASSERT_TRUE(su.is_object());
  EXPECT_TRUE(su["starts"].get<bool>());
  EXPECT_NEAR(su["run_up_time"].get<double>(), 0.915, 0.01);  // measured 0.915 s (multibody and reduced)
  ASSERT_FALSE(su["notes"].empty());
  const std::string note = su["notes"][0];
  for (const char* words : {"cannot show the switching transient", "understates the starting torque",
                            "against the catalogue's M_s = 280.1 N·m", "motor.model: park"})
    EXPECT_NE(note.find(words), std::string::npos) << words << " not in: " << note;
  const std::string text = startUpText(summary);
  EXPECT_NE(text.find("start-up     direct on line at t = 0 s, motor law: Kloss formula (static)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("note: The static Kloss law cannot show the switching transient"), std::string::npos) << text;
}


Scene defaultScene(const std::vector<std::string>& overrides) {
  return parseSceneFile(std::string(ROLLERDYN_SOURCE_DIR) + "/model/balanced-4cart.yaml", overrides);
}

nlohmann::json reducedSummary(const Scene& s) {
  const StartLoad load = startLoadOf(s);
  return makeSummary(s, runReducedModel(s), &load);
}

nlohmann::json multibodySummary(const Scene& s) {
  const StartLoad load = startLoadOf(s);
  return makeSummary(s, runMultibodyModel(s), &load);
}

// The heating check's start heat and the start-up answers' rotor energy loss are one computation
// (StartUp.h): the same number in summary.json, direct on line and in star-delta, in both models.
TEST(StartUpAnswers, TheHeatingChecksStartHeatIsTheStartsRotorEnergyLoss) {
  for (const std::vector<std::string>& o :
       {std::vector<std::string>{"motor.start.method=direct_on_line"},
        std::vector<std::string>{"motor.start.method=star_delta", "motor.start.changeover_time=0.6"}})
  for (const bool multibody : {false, true}) {
    const Scene s = defaultScene(o);
    const nlohmann::json j = multibody ? multibodySummary(s) : reducedSummary(s);
    const nlohmann::json& wr = j["sizing"]["motor"]["whole_run"];
    ASSERT_TRUE(j["start_up"].is_object());
    ASSERT_TRUE(wr["start_heat"].is_number()) << wr.dump();
    const double E = j["start_up"]["rotor_energy_loss"].get<double>();
    std::printf("  %-9s %s: start heat %.6g J, rotor energy loss of the start %.6g J, above steady running %.6g J\n",
                multibody ? "multibody" : "reduced", o.back().c_str(), wr["start_heat"].get<double>(), E,
                wr["start_heat_above_steady"].get<double>());
    EXPECT_GT(E, 0.0);
    EXPECT_EQ(wr["start_heat"].get<double>(), E);
    EXPECT_NEAR(wr["start_duration"].get<double>(),
                j["start_up"]["start_end"].get<double>() - j["start_up"]["t_on"].get<double>(), 1e-12);
    EXPECT_LE(wr["start_heat_above_steady"].get<double>(), E);
    EXPECT_TRUE(wr["starts_per_hour"].is_number());
  }
}

// The start-up verdict and the run's motion (RunMotion.h) never contradict each other.
TEST(StartUpAnswers, TheStartUpVerdictAgreesWithTheMotion) {
  // Held in star (the changeover speed is never reached): the stall rule skips the star rows, yet
  // the run ends with the drive at rest; it has not started, and both say so.
  const nlohmann::json held = reducedSummary(
      defaultScene({"loads.roller_force_direction=opposes_velocity", "motor.start.method=star_delta",
                    "motor.start.changeover_speed=80", "simulation.t_end=1.5"}));
  EXPECT_EQ(held["motion"], "stalled") << held["status"];
  EXPECT_FALSE(held["start_up"]["starts"].get<bool>());
  EXPECT_NE(held["start_up"]["verdict"].get<std::string>().find("does not start"), std::string::npos);
  // A run too short to settle: "starting", and the start-up answer says it is still starting
  // instead of giving a run-up time to the mean speed of a revolution that still rocks.
  const nlohmann::json starting = reducedSummary(defaultScene({"simulation.t_end=3", "crank.offset_deg=60"}));
  EXPECT_EQ(starting["motion"], "starting");
  EXPECT_FALSE(starting["start_up"]["starts"].get<bool>());
  EXPECT_TRUE(starting["start_up"]["still_starting"].get<bool>());
  EXPECT_TRUE(starting["start_up"]["run_up_time"].is_null());
  EXPECT_NE(starting["start_up"]["verdict"].get<std::string>().find("still starting"), std::string::npos)
      << starting["start_up"]["verdict"];
  // A switch-off: the steady window, the motion and the sizing are those of the running machine
  // before it (the coast-down is no steady state), as the start-up answers' are.
  const nlohmann::json off = reducedSummary(defaultScene({"motor.stop.t_off=5"}));
  EXPECT_EQ(off["motion"], "turning");
  EXPECT_TRUE(off["start_up"]["starts"].get<bool>());
  EXPECT_TRUE(off["steady_state"]["reached"].get<bool>());
  EXPECT_LE(off["steady_state"]["t_end"].get<double>(), 5.0);
  EXPECT_EQ(off["steady_state"]["t_begin"], off["start_up"]["steady"]["t_begin"]);
  EXPECT_GT(off["sizing"]["motor"]["torque_shaft"]["rms"].get<double>(), 1.0);  // not the coasting motor's 0
}

// A transient peak above the static characteristic's largest torque says which one it is: the
// trial read "largest 4561" beside a peak of 5005 N·m of the Park machine with no word on which.
TEST(StartUpAnswers, AParkPeakAboveTheBreakdownTorqueIsNamedAsTheSwitchingTransient) {
  const nlohmann::json j = reducedSummary(defaultScene({"motor.model=park", "simulation.t_end=3", "simulation.output_step=0.001"}));
  const double peak = j["start_up"]["motor_torque"]["peak"], largest = j["start_up"]["largest_torque_crank"];
  ASSERT_GT(peak, largest);
  const std::string text = startUpText(j);
  EXPECT_NE(text.find("(the peak is the switching transient: above the static characteristic's largest torque"),
            std::string::npos) << text;
}

// The sizing checks read the motor the run simulated: the second trial's circuit-law run with a
// mistyped motor.breakdown_torque = 700 was checked against 700 N·m (and M_n = 700/λ) while its
// motor, fitted to the catalogue, broke down at 517 N·m; its heating and breakdown verdicts moved
// with a key the law ignores.
TEST(StartUpAnswers, CatalogueLawsAreSizedWithTheirOwnBreakdownAndRatedTorque) {
  const std::vector<std::string> base = {"motor.model=circuit", "initial.crank_speed=10.4", "simulation.t_end=4"};
  std::vector<std::string> typo = base;
  typo.push_back("motor.breakdown_torque=700");
  const nlohmann::json a = reducedSummary(defaultScene(base)), b = reducedSummary(defaultScene(typo));
  const Scene s = defaultScene(base);
  const double M_kr = largestSteadyTorque(*makeMotorLaw(s), SupplyState{});
  for (const nlohmann::json* j : {&a, &b}) {
    const nlohmann::json& m = (*j)["sizing"]["motor"];
    EXPECT_NEAR(m["breakdown_torque"].get<double>(), M_kr, 1e-9 * M_kr) << m.dump();
    EXPECT_NEAR(m["nominal_torque"].get<double>(), s.induction.catalogue.nominalTorque(), 1e-9);
  }
  EXPECT_NEAR(M_kr, 517.14, 0.03 * 517.14);  // the catalogue's M_kr = 2.4·M_n, fitted within 3 %
  EXPECT_EQ(a["sizing"]["checks"].dump(), b["sizing"]["checks"].dump());  // the mistyped key changes nothing
}

// The second trial's six carts at 90° (circuit law): "motor_breakdown 1.235 FAIL ... peak 639 N·m"
// where the rotor torque ran -639 ... +474 N·m: the peak was braking, and nothing said so. The check
// names both peaks and, where the braking one decides, that the load drives the motor as a generator.
TEST(StartUpAnswers, ABrakingPeakIsNamedAsSuchInTheBreakdownCheck) {
  const nlohmann::json j = reducedSummary(defaultScene({"carts.count=6", "crank.offset_deg=90", "motor.model=circuit",
                                                         "initial.crank_speed=10.4", "simulation.t_end=10"}));
  const nlohmann::json& m = j["sizing"]["motor"];
  const double up = m["torque_motoring_peak"], down = m["torque_generating_peak"], M_kr = m["breakdown_torque"];
  ASSERT_GT(down, up);
  EXPECT_NEAR(m["peak_over_breakdown"].get<double>(), down / M_kr, 1e-12);
  int found = 0;
  for (const auto& c : j["sizing"]["checks"])
    if (c["check"] == "motor_breakdown") {
      ++found;
      EXPECT_NE(c["reason"].get<std::string>().find("the load drives the motor as a generator"), std::string::npos)
          << c["reason"];
    }
  EXPECT_EQ(found, 1);
}

// The second trial's six carts at 90° with a 1310 kg·m² flywheel, from rest: the breakdown FAIL
// said "the load needs more than the motor gives" where the motor's breakdown torque was 56 times
// the mean load (the starting torque against the start-angle load was the cause), and the heating
// reason weighed a start's heat against "steady running" that was a locked rotor.
TEST(StartUpAnswers, TheChecksOfADriveThatDoesNotTurnNameTheCause) {
  const nlohmann::json j = reducedSummary(defaultScene({"carts.count=6", "crank.offset_deg=90", "flywheel.inertia=1310",
                                                         "simulation.t_end=20"}));
  const std::string motion = j["motion"];
  ASSERT_TRUE(motion == "rocking" || motion == "stalled") << motion;
  for (const auto& c : j["sizing"]["checks"]) {
    const std::string reason = c["reason"];
    if (c["check"] == "motor_breakdown") {
      EXPECT_NE(reason.find("starting torque 1032 N·m at the crank"), std::string::npos) << reason;
      EXPECT_NE(reason.find("is below the load torque"), std::string::npos) << reason;
      EXPECT_EQ(reason.find("needs more than the motor gives"), std::string::npos) << reason;
    }
    if (c["check"] == "motor_heating") EXPECT_EQ(reason.find("steady running"), std::string::npos) << reason;
    // No steady state: the window deciding is not called one.
    if (c["check"] != "coupling" && c["check"] != "start") {
      EXPECT_EQ(c["window"], "run's last part (no steady state)") << c.dump();
    }
  }
}

// Kloss data that contradict the same motor's catalogue: the checks follow the simulated motor
// and say the verdict is unreliable (the third trial's motor.breakdown_torque = 800 turned the
// catalogue motor's 0.966 FAIL into 0.752 pass with only a warning on stderr).
TEST(StartUpAnswers, MotorChecksSayWhenTheMotorDataContradictTheCatalogue) {
  const nlohmann::json j = reducedSummary(
      defaultScene({"initial.crank_speed=10.4", "simulation.t_end=4", "motor.breakdown_torque=800"}));
  int flagged = 0;
  for (const auto& c : j["sizing"]["checks"])
    if (c["check"].get<std::string>().rfind("motor_", 0) == 0) {
      EXPECT_NE(c["reason"].get<std::string>().find("UNRELIABLE: motor.breakdown_torque = 800 N·m contradicts"),
                std::string::npos) << c["reason"];
      ++flagged;
    }
  EXPECT_EQ(flagged, 2);
  const nlohmann::json ok = reducedSummary(defaultScene({"initial.crank_speed=10.4", "simulation.t_end=4"}));
  for (const auto& c : ok["sizing"]["checks"]) EXPECT_EQ(c["reason"].get<std::string>().find("UNRELIABLE"), std::string::npos);
}

// A delta-rated motor started in star draws a third of the direct-on-line line current at the same
// speed (its windings see U/√3 at three times the equivalent star's impedance), as its torque is a
// third: the fourth trial read 154.3 A in star against 267.2 A direct on line (1/√3, the equivalent
// star's phase current under U/√3). At standstill, the first row, the circuit law is exact.
TEST(StartUpAnswers, AStarStartDrawsAThirdOfTheDirectOnLineCurrent) {
  const std::vector<std::string> base = {"motor.model=circuit", "simulation.t_end=0.2", "simulation.output_step=0.001"};
  std::vector<std::string> star = base;
  star.push_back("motor.start.method=star_delta");
  star.push_back("motor.start.changeover_speed=95");
  const RunResult dol = runReducedModel(defaultScene(base)), yd = runReducedModel(defaultScene(star));
  const double I_dol = dol.timeseries.column("stator_current")[0], I_star = yd.timeseries.column("stator_current")[0];
  const double M_dol = dol.timeseries.column("motor_torque")[0], M_star = yd.timeseries.column("motor_torque")[0];
  ASSERT_GT(I_dol, 100.0);
  EXPECT_NEAR(I_star / I_dol, 1.0 / 3.0, 1e-9);
  EXPECT_NEAR(M_star / M_dol, 1.0 / 3.0, 1e-9);
}

// A run that begins at speed holds no start: the second trial read "the drive starts ... 0.005 s
// after switch-on", start peaks and a start's rotor loss of 1.968e+04 J beside "the start's heat is
// not known". No run-up, no start peaks, no start loss; the stop is still answered, and a stop not
// reached within the run says so instead of "stopping time n/a s".
TEST(StartUpAnswers, ARunThatBeginsAtSpeedHasNoStartAnswers) {
  const nlohmann::json j = reducedSummary(
      defaultScene({"initial.crank_speed=10.4", "simulation.t_end=6", "motor.stop.t_off=5"}));
  const nlohmann::json& su = j["start_up"];
  ASSERT_TRUE(su.is_object());
  EXPECT_FALSE(su["from_rest"].get<bool>());
  EXPECT_FALSE(su["starts"].get<bool>());
  for (const char* k : {"run_up_time", "rotor_energy_loss"}) EXPECT_TRUE(su[k].is_null()) << k;
  EXPECT_TRUE(su["coupling_torque"]["peak"].is_null());
  EXPECT_NE(su["verdict"].get<std::string>().find("no start from rest in this run"), std::string::npos);
  const std::string text = startUpText(j);
  EXPECT_EQ(text.find("run-up"), std::string::npos) << text;
  EXPECT_EQ(text.find("rotor energy loss"), std::string::npos) << text;
  EXPECT_NE(text.find("switch-off at 5 s: not at rest when the run ends"), std::string::npos) << text;
  EXPECT_NE(sizingText(j).find("(begins at speed: no start-up)"), std::string::npos);
}

// The start ends where the crank speed settles, not where the steady window (the run's last
// revolutions) begins: in the trial its peaks, its rotor loss and the starts per hour moved with
// simulation.t_end. The same drive run for 10 s and for 20 s has the same start.
TEST(StartUpAnswers, TheStartEndsWhereTheCrankSpeedSettlesWhateverTheRunsLength) {
  const nlohmann::json a = reducedSummary(defaultScene({"simulation.t_end=10"}));
  const nlohmann::json b = reducedSummary(defaultScene({"simulation.t_end=20"}));
  for (const nlohmann::json* j : {&a, &b}) {
    ASSERT_TRUE((*j)["start_up"]["starts"].get<bool>());
    // The start holds the run-up and ends before the steady window of the long run.
    EXPECT_GE((*j)["start_up"]["start_end"].get<double>(), (*j)["start_up"]["run_up_time"].get<double>());
    EXPECT_NEAR((*j)["start_up"]["start_end"].get<double>(), (*j)["steady_state"]["t_settled"].get<double>(), 1e-12);
  }
  EXPECT_LT(b["start_up"]["start_end"].get<double>(), b["steady_state"]["t_begin"].get<double>() - 5.0);
  // t_settled is the start of a revolution; one revolution of the default drive lasts ~0.6 s and
  // both runs settle on the same one (their final speeds differ by far less than the 1e-3 tolerance).
  EXPECT_NEAR(a["start_up"]["start_end"].get<double>(), b["start_up"]["start_end"].get<double>(), 1e-6);
  EXPECT_NEAR(a["start_up"]["rotor_energy_loss"].get<double>(), b["start_up"]["rotor_energy_loss"].get<double>(),
              1e-6 * a["start_up"]["rotor_energy_loss"].get<double>());
  EXPECT_EQ(a["start_up"]["coupling_torque"]["peak"], b["start_up"]["coupling_torque"]["peak"]);
}

// The trial's six carts at 45° (circuit motor, rolling resistance): "the drive does not start ...
// cannot break away from rest there" while the load had driven the crank backwards to -144° at
// -4.8 rad/s and it swung for 4 s before it was held at -90°. The status and the start-up verdict
// say how the crank moved.
TEST(StartUpAnswers, ADriveTheLoadTurnsBackwardsSaysSo) {
  const nlohmann::json j =
      reducedSummary(defaultScene({"carts.count=6", "crank.offset_deg=45", "motor.model=circuit",
                                   "loads.rolling_resistance=0.05"}));
  ASSERT_EQ(j["motion"], "stalled") << j["status"];
  const std::string status = j["status"], verdict = j["start_up"]["verdict"];
  for (const std::string& text : {status, verdict}) {
    EXPECT_NE(text.find("the crank did not stay at the start angle: the load drove it backwards, over -144.1 ... 0 deg, swinging"), std::string::npos) << text;
    EXPECT_EQ(text.find("break away from rest"), std::string::npos) << text;
  }
  // And a drive held where it started says nothing of the kind.
  const nlohmann::json held = reducedSummary(defaultScene({"loads.roller_force_direction=opposes_velocity"}));
  ASSERT_EQ(held["motion"], "stalled");
  EXPECT_EQ(held["status"].get<std::string>().find("did not stay"), std::string::npos) << held["status"];
}

// A drive that never turns has no start and no steady state: the trial read "run-up time (to 95 %
// of 0.0005305 rad/s)" and a "most negative" motor torque of +1032 N·m. The console says the drive
// does not start, and its peaks are over the run against the run's last part.
TEST(StartUpAnswers, ADriveThatDoesNotStartHasNoRunUpAndItsPeaksAreOverTheRun) {
  const nlohmann::json j =
      reducedSummary(defaultScene({"loads.roller_force_direction=opposes_velocity", "carts.count=6", "crank.offset_deg=60"}));
  ASSERT_FALSE(j["start_up"]["starts"].get<bool>());
  ASSERT_FALSE(j["start_up"]["still_starting"].get<bool>());
  EXPECT_GT(j["start_up"]["motor_torque"]["min"].get<double>(), 0.0);  // held at standstill, never negative
  const std::string text = startUpText(j);
  EXPECT_EQ(text.find("95 %"), std::string::npos) << text;
  EXPECT_EQ(text.find("most negative"), std::string::npos) << text;
  EXPECT_EQ(text.find("in the start"), std::string::npos) << text;
  EXPECT_NE(text.find("run-up time                   none: the drive does not start"), std::string::npos) << text;
  EXPECT_NE(text.find("over the run"), std::string::npos) << text;
  EXPECT_EQ(text.find("switching transient: above"), std::string::npos) << text;  // a static law never exceeds it
  // The windows in words: the trial read "the last 0 revolutions" and "over the steady window"
  // of a drive held at standstill.
  EXPECT_NE(summaryText(j).find("metrics window: the last 20 % of the run (it holds no whole crank revolution)"),
            std::string::npos) << summaryText(j);
  EXPECT_NE(sizingText(j).find("drive sizing over the run's last part (no steady state)"), std::string::npos);
  // The whole running part of the run is the interval of the peaks.
  EXPECT_NEAR(j["start_up"]["start_end"].get<double>(), j["steady_state"]["t_end"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace rollerdyn
