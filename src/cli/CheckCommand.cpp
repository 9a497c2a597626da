// `rollerdyn check SCENE`: validate the scene and show what the multibody model would build.
#include <iostream>

#include "analysis/FrictionChecks.h"
#include "cli/Commands.h"
#include "scene/Plausibility.h"
#include "multibody/MultibodyModel.h"
#include "scene/SceneParser.h"

namespace rollerdyn::cli {

int runCheck(const SceneArgs& args) {
  const Scene scene = parseSceneFile(args.scene_path, args.overrides);
  const MultibodyModel model(scene);
  const MultibodyInventory& inv = model.inventory();
  std::cout << "scene " << scene.name << ": valid (" << scene.source_path << ")\n";
  for (const std::string& w : plausibilityWarnings(scene)) std::cerr << "rollerdyn: warning: " << w << '\n';
  // Effects in words (the scene key that sets each); the count of force elements is what the
  // multibody model adds to Simbody's system for them.
  std::cout << "effects built:\n";
  for (const auto& e : inv.effects) std::cout << "  " << effectWords(e) << '\n';
  std::cout << "force elements: " << inv.force_elements.size();
  std::cout << "\nbodies: " << inv.bodies << "\nmobilities: " << inv.mobilities
            << "\nconstraints: " << inv.constraints << " (" << inv.constraint_equations
            << " equations)\ndegrees of freedom: " << inv.degrees_of_freedom << '\n';
  std::cout << lockingReport(scene);
  for (const std::string& w : lockingWarnings(scene)) std::cerr << "rollerdyn: warning: " << w << '\n';
  return 0;
}

}  // namespace rollerdyn::cli
