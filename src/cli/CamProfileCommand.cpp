// `rollerdyn cam-profile SCENE [--set k=v]... [--out DIR] [--samples N] [--compare] [--model M]`:
// the cam of Loveikin and Pochka (cam drive paper) for a scene: cam_profile.csv (motion law and radius ρ(θ), eq. (29)-(43)),
// figures, and with --compare the cam-driven cart against a crank-driven cart of equal stroke
// and cycle time (cam_vs_crank.csv / .json).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "cli/SceneOptions.h"
#include "cli/UsageError.h"
#include "io/AtomicFile.h"
#include "report/Gnuplot.h"
#include "report/OutputDir.h"
#include "scene/SceneParser.h"
#include "studies/CamStudy.h"

namespace rollerdyn::cli {

namespace {

struct CamArgs {
  SceneArgs scene;
  std::string out_dir, model = "reduced";
  int samples = 721;
  bool compare = false;
};

nlohmann::json responseJson(const DriveResponse& r) {
  return {{"drive", r.drive}, {"status", r.status}, {"complete", r.complete}, {"steady_state_reached", r.steady},
          {"omega_mean", r.omega_mean}, {"t3", r.t3}, {"delta", r.delta}, {"stroke", r.stroke},
          {"velocity_peak", r.velocity_peak}, {"accel_peak", r.accel_peak},
          {"accel_peak_kinematic", r.accel_peak_kinematic}, {"jerk_peak", r.jerk_peak},
          {"jerk_peak_kinematic", r.jerk_peak_kinematic}, {"coupling_torque_max", r.coupling_torque_max},
          {"coupling_torque_min", r.coupling_torque_min}, {"motor_torque_abs_max", r.motor_torque_max},
          {"drive_force_max", r.force_max}, {"drive_force_min", r.force_min},
          {"drive_force_abs_peak", r.force_abs_peak}};
}

// The motion law x, v, a, jerk against the cam angle (eq. (29)-(34)).
void drawCamMotionLaw(const Table& t, const std::string& stem) {
  PlotSpec law;
  law.title = "Loveikin and Pochka (cam drive paper) motion law at constant crank speed (eq. (29)-(34))";
  law.xlabel = "cam angle [deg]";
  law.ylabel = "x [m], v [m/s], a [m/s²], jerk [m/s³]";
  const char* names[] = {"x", "v", "a", "jerk"};
  for (const char* n : names) {
    PlotSeries s;
    s.title = n;
    s.x = t.column("theta_deg");
    s.y = t.column(n);
    law.series.push_back(s);
  }
  renderPlot(law, stem);
}

// The cam's shape ρ(θ) in the cam frame (eq. (38)-(43)).
void drawCamShape(const Table& t, const std::string& stem) {
  PlotSpec shape;
  shape.title = "cam profile rho(theta) = b/2 + x(theta) (eq. (38)-(43)), cam frame";
  shape.xlabel = "X [m]";
  shape.ylabel = "Y [m]";
  shape.width = shape.height = 700;
  PlotSeries s;
  s.title = "profile";
  const auto th = t.column("theta"), rho = t.column("rho");
  for (std::size_t i = 0; i < th.size(); ++i) {
    s.x.push_back(rho[i] * std::cos(-th[i]));
    s.y.push_back(rho[i] * std::sin(-th[i]));
  }
  shape.series.push_back(s);
  renderPlot(shape, stem);
}

// The cam-driven cart against a crank-driven one of equal stroke and cycle time.
void writeCamVsCrank(const CamArgs& a, const std::string& out) {
  const CamVsCrank c = compareCamWithCrank(a.scene.scene_path, a.scene.overrides, a.model);
  writeFileAtomic(out + "/cam_vs_crank.csv", camVsCrankCsv(c));
  nlohmann::json j = {{"scene", a.scene.scene_path}, {"overrides", a.scene.overrides}, {"model", c.model},
                      {"note", c.note}, {"cam", responseJson(c.cam)}, {"crank", responseJson(c.crank)}};
  writeFileAtomic(out + "/cam_vs_crank.json", j.dump(2) + "\n");
  std::cout << "cam vs crank (" << c.model << " model, steady state):\n" << camVsCrankCsv(c);
  if (!c.note.empty()) std::cout << "note: " << c.note << "\n";
}

int runCamProfile(const CamArgs& a) {
  const Scene scene = parseSceneFile(a.scene.scene_path, a.scene.overrides);
  const std::string out = a.out_dir.empty() ? defaultOutDir(scene.name) + "/cam" : a.out_dir;
  prepareOutputDir(out);  // before the runs: a bad --out fails now
  const Table t = camProfileTable(scene, a.samples);
  writeCsvAtomic(out + "/cam_profile.csv", t);
  const double w = camReferenceSpeed(scene);
  std::printf("cam of %s: stroke %.4g m, pusher distance (cam diameter) %.4g m, t3 = pi/omega = %.4g s at "
              "omega = %.4g rad/s\n",
              scene.name.c_str(), scene.cam.stroke, scene.cam.pusher_distance, M_PI / w, w);
  if (gnuplotAvailable()) {
    drawCamMotionLaw(t, out + "/cam_motion_law");
    drawCamShape(t, out + "/cam_profile");
  } else {
    std::cout << "gnuplot not found: no figures\n";
  }
  if (a.compare) writeCamVsCrank(a, out);
  std::cout << "outputs in " << out << "/\n";
  return 0;
}

}  // namespace

Subcommand addCamProfileCommand(CLI::App& app) {
  auto args = std::make_shared<CamArgs>();
  CLI::App* cmd = app.add_subcommand("cam-profile",
                                     "cam drive with optimal reversal of Loveikin and Pochka: motion law and cam profile to CSV; --compare runs "
                                     "the cam against a crank of equal stroke");
  addSceneFile(*cmd, args->scene, "scene file (YAML) with cam.stroke");
  addSceneOverrides(*cmd, args->scene);
  cmd->add_option("--out", args->out_dir, "output folder (default out/<scene name>/cam)");
  cmd->add_option("--samples", args->samples, "rows over one cam turn (default 721: every 0.5 deg)")
      ->check(CLI::Range(2, 1000000));
  cmd->add_flag("--compare", args->compare,
                "also simulate the scene with drive.type=cam and drive.type=crank and compare peaks");
  cmd->add_option("--model", args->model, "model for --compare: reduced (default) or multibody")
      ->check(oneOf({"multibody", "reduced"}));
  cmd->footer("Example:\n  rollerdyn cam-profile model/cam-drive.yaml --compare --out out/cam");
  return {cmd, [args] { return runCamProfile(*args); }};
}

}  // namespace rollerdyn::cli
