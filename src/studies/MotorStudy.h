// The scene's induction motor on its own (`rollerdyn motor`, Python's rd.fit_motor): the
// equivalent circuit from motor.circuit or fitted to motor.catalogue (Pedra (2008), CatalogueFit.h),
// the model beside the catalogue at every catalogue point (with Kloss's torques), and the steady
// torque-slip and current-slip curves of every motor model (docs/motor.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/Table.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct MotorStudy {
  nlohmann::json json;        // motor.json: Kloss's data, the machine, the fit, the catalogue points
  Table curves;               // motor_curves.csv: slip, rotor speeds, torques and currents, 0 <= s <= 1
  std::string catalogue_csv;  // motor_catalogue.csv ("" without catalogue points)
  std::string text;           // what `rollerdyn motor` prints
  bool has_machine = false;   // a circuit was given or fitted
};

// `scene_label`: the scene file as given (motor.json "scene"); `overrides`: the --set options.
// Throws std::invalid_argument where the fit cannot be made.
MotorStudy studyMotor(const Scene& scene, const std::string& scene_label, const std::vector<std::string>& overrides);

// Writes motor.json, motor_curves.csv, motor_catalogue.csv (when there are catalogue points) and,
// with gnuplot, the figures motor_torque_slip and motor_current_slip (PNG and SVG) into out_dir
// (which must exist). Returns a line saying what is missing ("" when nothing is).
std::string writeMotorStudy(const std::string& out_dir, const Scene& scene, const MotorStudy& study);

}  // namespace rollerdyn
