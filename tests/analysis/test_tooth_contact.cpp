// The teeth's contact over the steady window (analysis/ToothContact.h) from a made-up timeseries
// whose answers are known by hand: twist 0.001 + 0.002·sin(2πt) rad with a total backlash of
// 0.002 rad (b = 0.001) is inside the gap wherever sin(2πt) ≤ 0, half of every 1 s period; the
// teeth meet again once a period, just after t = 1, 2, ... s; the crank turns 2 revolutions per
// second; the coupling torque c·(twist − b) peaks at c·0.002 = 400 N·m (c = 2e5 N·m/rad).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/ToothContact.h"
#include "physics/CouplingLaw.h"

namespace rollerdyn {
namespace {

Scene backlashScene(double backlash) {
  Scene s{};
  s.coupling.type = CouplingType::Elastic;
  s.coupling.stiffness = 2e5;
  s.coupling.damping = 0;
  s.reducer.backlash = backlash;
  return s;
}

RunResult run(const Scene& s) {
  const CouplingLaw law = couplingLaw(s);
  RunResult r;
  r.timeseries.columns = {"t", "phi_crank", "twist", "coupling_torque", "tooth_contact"};
  for (int i = 0; i <= 30000; ++i) {
    const double t = 1e-4 * i, q = 0.001 + 0.002 * std::sin(2.0 * M_PI * t);
    r.timeseries.rows.push_back({t, 4.0 * M_PI * t, q, couplingTorque(law, q, 0.0).torque,
                                 static_cast<double>(toothContact(law, q))});
  }
  return r;
}

SteadyState window() {  // t = 0.75 ... 2.75 s
  SteadyState ss;
  ss.reached = true;
  ss.t_begin = 0.75;
  ss.t_end = 2.75;
  ss.row_begin = 7500;
  ss.row_end = 27501;
  return ss;
}

TEST(ToothContact, CountsImpactsTimeApartAndPeakImpactTorqueOverTheWindow) {
  const Scene s = backlashScene(0.002);
  const ToothContactSummary c = computeToothContact(s, run(s), window(), true);
  EXPECT_EQ(c.verdict, "teeth separate");
  EXPECT_NEAR(c.revolutions, 4.0, 1e-9);
  EXPECT_EQ(c.impacts, 2);  // just after t = 1 and t = 2 s
  EXPECT_NEAR(c.impacts_per_revolution, 0.5, 1e-9);
  // apart on (0.75, 1), (1.5, 2), (2.5, 2.75): 1 s of 2 s
  EXPECT_NEAR(c.out_of_contact_fraction, 0.5, 1e-6);
  EXPECT_NEAR(c.peak_impact_torque, 400.0, 1e-3);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("teeth separate in steady running"), std::string::npos) << c.warnings[0];
  EXPECT_NE(c.warnings[0].find("50 %"), std::string::npos) << c.warnings[0];
}

TEST(ToothContact, TeethThatNeverPartStayInContact) {
  const Scene s = backlashScene(0.0002);  // b = 1e-4
  RunResult r = run(s);
  for (auto& row : r.timeseries.rows) {  // twist 0.004 + 0.002·sin: always beyond b
    row[2] += 0.003;
    row[4] = static_cast<double>(toothContact(couplingLaw(s), row[2]));
  }
  const ToothContactSummary c = computeToothContact(s, r, window(), true);
  EXPECT_EQ(c.verdict, "teeth stay in contact");
  EXPECT_EQ(c.impacts, 0);
  EXPECT_EQ(c.out_of_contact_fraction, 0.0);
  EXPECT_TRUE(c.warnings.empty());
}

TEST(ToothContact, NotApplicableWithoutBacklashOrSteadyWindow) {
  const Scene none = backlashScene(0.0);
  ToothContactSummary c = computeToothContact(none, run(none), window(), true);
  EXPECT_EQ(c.verdict, "not applicable");
  EXPECT_NE(c.reason.find("reducer.backlash: 0"), std::string::npos) << c.reason;
  const Scene s = backlashScene(0.002);
  SteadyState ss = window();
  ss.reached = false;
  ss.not_reached = "steady state not reached within the run: run longer (simulation.t_end)";
  c = computeToothContact(s, run(s), ss, false);
  EXPECT_EQ(c.verdict, "not applicable");
  EXPECT_EQ(c.reason, ss.not_reached);
  const nlohmann::json j = toothContactJson(c);
  EXPECT_TRUE(j["impacts_per_revolution"].is_null());
  EXPECT_EQ(j["verdict"], "not applicable");
}

}  // namespace
}  // namespace rollerdyn
