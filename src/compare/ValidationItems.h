// Validation items kept in files of their own (drive sizing, the motor law, kinematics, sweeps,
// and whatever the team adds: motor models, start-up, torsional modes): each computes one section
// of report.md with its claims (ValidationClaims.h), run by `rollerdyn validate` after the
// built-in sections (1)-(4), in the order of the command's list.
//
// To add one: write `ValidationSection yourChecks(const ItemContext& ctx)` in a new file of the
// layer that has what it needs (src/compare/Validation<Topic>.cpp, or src/studies/... when it
// runs sweeps), declare it in that layer's header (this one for src/compare), and add one line to
// the list in src/cli/ValidationItemList.cpp. An exception thrown by an item becomes a FAILED
// claim of its section (validate then exits 1); it never stops the other items.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "compare/ValidationClaims.h"
#include "scene/Scene.h"

namespace rollerdyn::validation {

// What an item may use of the running suite.
struct ItemContext {
  std::string model_dir = "model";                  // the shipped scene files
  bool quick = false;                               // validate --quick: keep it short
  const std::atomic<bool>* interrupt = nullptr;     // Ctrl-C
  std::function<void(const std::string&)> log_line; // progress on stderr (may be empty)

  // The shipped scene `file` (model_dir) with `sets` applied as --set values.
  Scene load(const std::string& file, const std::vector<std::string>& sets = {}) const;
  std::string path(const std::string& file) const { return model_dir + "/" + file; }
  // The same as a command line for the report: "rollerdyn <verb> model/<file> --set ...".
  std::string command(const std::string& verb, const std::string& file, const std::vector<std::string>& sets = {}) const;
  void log(const std::string& line) const;
  bool interrupted() const;  // return what is computed so far
};

using ValidationItem = std::function<ValidationSection(const ItemContext&)>;
struct NamedItem {
  std::string name;  // one line in the log
  ValidationItem run;
};

// Runs the items in order, an exception turned into a FAILED claim of the item's section.
std::vector<ValidationSection> runValidationItems(const ItemContext& ctx, const std::vector<NamedItem>& items);

// Drive sizing (src/analysis/DriveSizing.h) recomputed by hand from the columns of the tables a
// run writes (ValidationSizing.cpp).
ValidationSection driveSizingChecks(const ItemContext& ctx);

// The motor_torque column of both models against Kloss's formula written out from the scene
// file's catalogue data (ValidationMotorLaw.cpp).
ValidationSection motorLawChecks(const ItemContext& ctx);

// Each cart's x_cart and v_cart columns against the slider-crank closed form at the crank angle
// of its crank (offset and side), both models (ValidationKinematics.cpp).
ValidationSection kinematicsChecks(const ItemContext& ctx);

// The energy audit of every shipped scene in both models closes at accuracy 1e-9
// (ValidationEnergy.cpp).
ValidationSection energyBalanceChecks(const ItemContext& ctx);

}  // namespace rollerdyn::validation
