// The CSV header convention name[unit] (io/Table.h): one table, applied by the writer and
// undone by the reader, so code keeps using bare names.
#include <gtest/gtest.h>

#include "io/AtomicFile.h"
#include "io/Table.h"

using namespace rollerdyn;

TEST(ColumnUnits, KnownColumnsCarryTheirUnits) {
  EXPECT_EQ(headerWithUnit("t"), "t[s]");
  EXPECT_EQ(headerWithUnit("omega_crank"), "omega_crank[rad/s]");
  EXPECT_EQ(headerWithUnit("eps_crank"), "eps_crank[rad/s^2]");
  // Torques say at which shaft they are (the console's motor torque is at the rotor).
  EXPECT_EQ(headerWithUnit("coupling_torque"), "coupling_torque[N*m at the crank axis]");
  EXPECT_EQ(headerWithUnit("motor_torque"), "motor_torque[N*m at the crank axis]");
  EXPECT_EQ(headerWithUnit("v_cart_12"), "v_cart_12[m/s]");
  EXPECT_EQ(headerWithUnit("N_front_3"), "N_front_3[N]");
  EXPECT_EQ(headerWithUnit("crankpin_y_1"), "crankpin_y_1[N]");
  EXPECT_EQ(headerWithUnit("omega_crank_multibody"), "omega_crank_multibody[rad/s]");
  EXPECT_EQ(headerWithUnit("N_rear_2_reduced_kinetostatic"), "N_rear_2_reduced_kinetostatic[N]");
  EXPECT_EQ(headerWithUnit("v_cart_x"), "v_cart_x");  // not a cart number: unknown, bare
  EXPECT_EQ(headerWithUnit("psi_sim"), "psi_sim");
}

TEST(ColumnUnits, StripUnitUndoesTheWriter) {
  EXPECT_EQ(stripUnit("omega_crank[rad/s]"), "omega_crank");
  EXPECT_EQ(stripUnit("t"), "t");
  EXPECT_EQ(stripUnit("[odd]"), "[odd]");
  Table t;
  t.columns = {"t", "F_rod_1", "custom"};
  t.rows = {{0, 1, 2}};
  const std::string csv = toCsv(t);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t[s],F_rod_1[N],custom");
}
