#include <gtest/gtest.h>

#include <iostream>

#include "multibody/MultibodySimulation.h"
#include "support/Seed000Scene.h"

using namespace rollerdyn;

TEST(Smoke, Seed000Runs) {
  Scene sc = test_scenes::seed000Scene();
  sc.simulation.t_end = 1.0;
  MultibodyModel model(sc);
  RunResult r = simulateMultibody(model);
  const auto& last = r.timeseries.rows.back();
  std::cout << "status " << r.stats.status << " steps " << r.stats.steps << " real " << r.stats.realizations
            << " cpu " << r.stats.cpu_seconds << " omega " << last[4] << " cerr " << r.stats.constraint_error_max
            << " eres " << r.energy.residualRelative() << " motorW " << r.energy.motor_work << "\n";
  for (size_t i = 0; i < r.reactions.columns.size(); ++i)
    std::cout << r.reactions.columns[i] << "=" << r.reactions.rows.back()[i] << " ";
  std::cout << "\n";
  EXPECT_TRUE(r.stats.complete);
}
