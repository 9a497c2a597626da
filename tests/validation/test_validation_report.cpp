// The validation report's writer and findings on synthetic results: every claim printed with
// its outcome, a failed comparison printed as FAILED, numbers derived by hand here, and no source
// file names in what the user reads.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "compare/PaperFindings.h"
#include "compare/ValidationSuite.h"
#include "support/Loveikin2018Scene.h"

namespace rollerdyn::validation {
namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

SweepPoint point(double x, double k, double ours, double published, bool rotating = true) {
  SweepPoint p;
  p.x = x;
  p.k = k;
  p.reduced.complete = true;
  p.reduced.rotating = rotating;
  p.reduced.torque_swing = ours;
  p.variant = p.reduced;
  p.has_variant = true;
  p.has_published = true;
  p.published["coupling_torque_swing"] = published;
  return p;
}

// The Table 1 sweep with the swings at k = 2000 and 8000 at 60° and 90° (published values of
// the paper's Table 1 at those points).
PaperSweep table1(double ours_90_k8000) {
  PaperSweep p;
  p.id = "loveikin2018";
  p.points = {point(0, 2000, 21000, 7966.58, false), point(30, 2000, 15000, 2229.0, false), point(60, 2000, 12740, 1273.0),
              point(90, 2000, 656, 148.67), point(0, 8000, 19860, 7456.24, false), point(30, 8000, 13810, 2189.0, false),
              point(60, 8000, 11850, 1248.0), point(90, 8000, ours_90_k8000, 130.93)};
  for (double x : {0.0, 30.0, 60.0, 90.0}) {
    SweepPoint s;
    s.x = x;
    s.k = 8000;
    s.reduced.complete = false;
    s.reduced.status = "motor stalled at t = 0 s";
    p.other_reading.push_back(s);
  }
  return p;
}

const Finding* findingStarting(const std::vector<Finding>& fs, const std::string& prefix) {
  for (const auto& f : fs)
    if (f.text.rfind(prefix, 0) == 0) return &f;
  return nullptr;
}

TEST(PaperFindings, TrendWithDampingIsAComparisonOfTheRun) {
  const Scene sc = test_scenes::loveikin2018Scene();
  // Ours falls from k = 2000 to 8000 at 60° and 90°, as the paper's: holds.
  auto f = findingsLoveikin2018(table1(460), {}, sc);
  const Finding* trend = findingStarting(f, "Trend with damping");
  ASSERT_NE(trend, nullptr);
  EXPECT_EQ(trend->verdict, Finding::Verdict::Holds) << trend->text;
  // Ours rises at 90° (700 > 656) while the paper's falls: printed as failed, with the numbers.
  f = findingsLoveikin2018(table1(700), {}, sc);
  trend = findingStarting(f, "Trend with damping");
  ASSERT_NE(trend, nullptr);
  EXPECT_EQ(trend->verdict, Finding::Verdict::Fails);
  EXPECT_TRUE(contains(trend->text, "disagrees at 90°")) << trend->text;
  EXPECT_TRUE(contains(trend->text, "656 → 700")) << trend->text;
}

TEST(PaperFindings, OtherReadingStallsOnlyWhenEveryRunStalled) {
  const Scene sc = test_scenes::loveikin2018Scene();
  PaperSweep p = table1(460);
  auto other = [&](const std::vector<Finding>& fs) { return findingStarting(fs, "The other reading"); };
  const std::vector<Finding> f1 = findingsLoveikin2018(p, {}, sc);
  ASSERT_NE(other(f1), nullptr);
  EXPECT_EQ(other(f1)->verdict, Finding::Verdict::Holds);
  // Mean torque of the other reading by hand: n·(F1 + F2)·2r/π = 4·15924·0.4/π = 8110 N·m; the
  // breakdown torque at the crank M_kr·u·η = 517.14·9.8·0.9 = 4561 N·m.
  EXPECT_TRUE(contains(other(f1)->text, "= 8.1 kN·m")) << other(f1)->text;
  EXPECT_TRUE(contains(other(f1)->text, "= 4.6 kN·m")) << other(f1)->text;
  p.other_reading[2].reduced.complete = true;
  p.other_reading[2].reduced.status = "completed";
  const std::vector<Finding> f2 = findingsLoveikin2018(p, {}, sc);
  EXPECT_EQ(other(f2)->verdict, Finding::Verdict::Fails);
  EXPECT_TRUE(contains(other(f2)->text, "does not stall at 60°")) << other(f2)->text;
}

TEST(PaperFindings, LoadHarmonicByHand) {
  // First harmonic swing of the as-printed load torque at Δφ = 0: all four cranks in phase,
  // 2·(F1 + F2)·r·4 = 2·15924·0.2·4 = 25478 N·m; at 90° the four phasors cancel.
  const auto f = findingsLoveikin2018(table1(460), {}, test_scenes::loveikin2018Scene());
  const Finding* load = findingStarting(f, "Load reading as printed");
  ASSERT_NE(load, nullptr);
  EXPECT_TRUE(contains(load->text, "2.55e+04 N·m at 0°")) << load->text;
  EXPECT_TRUE(contains(load->text, "0 N·m at 90°")) << load->text;
  EXPECT_EQ(load->verdict, Finding::Verdict::Holds);  // published 7967, 2229, 1273 < half of it
}

ComparisonCase comparison(const std::string& label, double accuracy, double w, double m, bool pass) {
  ComparisonCase c;
  c.label = label;
  c.description = "synthetic";
  c.accuracy = accuracy;
  c.max_rel_omega = w;
  c.max_rel_torque = m;
  c.complete = true;
  c.pass = pass;
  c.command = "rollerdyn compare model/x.yaml";
  return c;
}

TEST(ValidationReport, VerdictsAndNumbersAsComputed) {
  ValidationResults r;
  r.equivalence = {comparison("E0", 1e-9, 3e-8, 2e-7, true), comparison("E1", 1e-11, 2e-6, 3e-6, false)};
  r.equivalence[1].explanation = "above target";
  // E4 falls tenfold per decade; E3 does not fall at all (a modelling difference would not).
  r.convergence = {comparison("E4", 1e-8, 1e-6, 1e-5, false), comparison("E4", 1e-10, 1e-8, 1e-7, true),
                   comparison("E3", 1e-8, 1e-6, 1e-5, false), comparison("E3", 1e-10, 1e-6, 1e-5, false)};
  ComparisonCase d = comparison("D5", 1e-9, 9e-4, 0.02, false);
  d.explanation = "Claim: first order.";
  d.verdict = Finding::Verdict::Fails;
  r.differences = {d};
  PaperSweep p = table1(700);
  p.title = "synthetic";
  p.scene_file = "balanced-4cart.yaml";
  p.start = {"initial.crank_speed=10.42"};
  p.findings = findingsLoveikin2018(p, {}, test_scenes::loveikin2018Scene());
  r.papers = {p};
  const ValidationReport rep = buildValidationReport(r, "figures");
  const std::string& md = rep.markdown;
  EXPECT_TRUE(contains(md, "**FAIL** above target"));                      // E1 fails the target
  EXPECT_TRUE(contains(md, "E4: from 1e-08 to 1e-10 the crank-speed difference falls by 10x"));
  EXPECT_TRUE(contains(md, "falls by 1x and the coupling-torque difference by 1x per decade (at least 3x required): **FAILED**"));
  EXPECT_TRUE(contains(md, "Claim: first order. **FAILED**"));
  EXPECT_TRUE(contains(md, "it disagrees at 90°"));
  EXPECT_TRUE(contains(md, "`--set initial.crank_speed=10.42`"));
  for (const char* internal : {"src/", ".cpp", ".h)", "seed0", "issue"}) EXPECT_FALSE(contains(md, internal)) << internal;
  // results.json carries the same verdicts; the result tables are named by paper.
  const auto& fj = rep.results["papers"]["loveikin2018"]["findings"];
  bool failed = false;
  for (const auto& f : fj) failed = failed || f["verdict"] == "failed";
  EXPECT_TRUE(failed);
  bool table1_csv = false;
  for (const auto& [name, t] : rep.tables) table1_csv = table1_csv || (name == "loveikin2018_table1.csv" && t.rows.size() == 8);
  EXPECT_TRUE(table1_csv);
}

// Every verdict printed is a claim: counted in the summary, carried by results.json, and the
// exit status is 1 as soon as one is FAILED or one equivalence case fails.
TEST(ValidationReport, EveryPrintedVerdictIsCountedAndDecidesTheExitStatus) {
  ValidationResults r;
  r.equivalence = {comparison("E0", 1e-9, 3e-8, 2e-7, true)};
  ComparisonCase d = comparison("D5", 1e-9, 9e-4, 0.02, false);
  d.explanation = "Claim: first order.";
  d.verdict = Verdict::Holds;
  r.differences = {d};
  PaperSweep p = table1(460);  // every finding holds: the gap is explained
  p.title = "synthetic";
  p.findings = findingsLoveikin2018(p, {}, test_scenes::loveikin2018Scene());
  r.papers = {p};
  ValidationSection item("extra", "An item of its own");
  item.claim(true, "a comparison that held");
  r.sections = {item};
  ValidationReport rep = buildValidationReport(r, "figures");
  const ClaimCount n = countClaims(rep.claims);
  EXPECT_EQ(n.failed, 0);
  EXPECT_EQ(n.gaps, 1);
  EXPECT_GE(n.holds, 3);  // D5, the findings' claims, the item's claim
  EXPECT_EQ(validationExitStatus(r, rep), 0);
  EXPECT_TRUE(contains(rep.markdown, "## (5) An item of its own"));
  EXPECT_TRUE(contains(rep.markdown, "- **extra.1** a comparison that held **holds**"));
  EXPECT_TRUE(contains(rep.markdown, "**gap, explained**"));
  EXPECT_EQ(rep.results["claim_count"]["gap_explained"], 1);
  EXPECT_TRUE(contains(validationSummary(r, rep), " claims: ")) << validationSummary(r, rep);

  // One claim FAILED (the damping trend): exit 1, the summary names it, the gap is no longer
  // explained (its reason's own claim failed).
  r.papers[0] = table1(700);
  r.papers[0].title = "synthetic";
  r.papers[0].findings = findingsLoveikin2018(r.papers[0], {}, test_scenes::loveikin2018Scene());
  rep = buildValidationReport(r, "figures");
  EXPECT_EQ(countClaims(rep.claims).failed, 2);  // the trend and the gap
  EXPECT_EQ(countClaims(rep.claims).gaps, 0);
  EXPECT_EQ(validationExitStatus(r, rep), 1);
  EXPECT_TRUE(contains(validationSummary(r, rep), "FAILED loveikin2018.")) << validationSummary(r, rep);
  bool failed_in_json = false;
  for (const auto& c : rep.results["claims"]) failed_in_json = failed_in_json || c["verdict"] == "failed";
  EXPECT_TRUE(failed_in_json);

  // Claims all hold but an equivalence case fails: exit 1 as well.
  r.papers.clear();
  r.equivalence.push_back(comparison("E1", 1e-11, 2e-6, 3e-6, false));
  rep = buildValidationReport(r, "figures");
  EXPECT_EQ(countClaims(rep.claims).failed, 0);
  EXPECT_EQ(validationExitStatus(r, rep), 1);
}

TEST(ValidationClaims, SectionNumbersItsClaimsAndPrintsTheirVerdicts) {
  ValidationSection s("k", "Title");
  s.text() << "Intro.\n\n";
  EXPECT_EQ(s.claim(true, "A held."), "k.1");
  EXPECT_EQ(s.claim(false, "B did not."), "k.2");
  EXPECT_EQ(s.gap(true, "C differs by 12 %.", "the inputs."), "k.3");
  EXPECT_EQ(s.gap(false, "D differs by 40 %.", "a reason whose check failed."), "k.4");
  const ClaimCount n = countClaims(s.claims());
  EXPECT_EQ(n.holds, 1);
  EXPECT_EQ(n.failed, 2);
  EXPECT_EQ(n.gaps, 1);
  const std::string md = s.markdown();
  EXPECT_TRUE(contains(md, "Intro."));
  EXPECT_TRUE(contains(md, "- **k.2** B did not. **FAILED**"));
  EXPECT_TRUE(contains(md, "- **k.3** C differs by 12 %. Why: the inputs. **gap, explained**"));
  const ValidationSection copy = s;  // a section is a value
  EXPECT_EQ(copy.markdown(), md);
}

TEST(ValidationItems, AnItemThatThrowsIsAFailedClaimAndTheOthersStillRun) {
  ItemContext ctx;
  std::vector<NamedItem> items = {
      {"broken", [](const ItemContext&) -> ValidationSection { throw std::runtime_error("no such scene"); }},
      {"fine", [](const ItemContext&) {
         ValidationSection s("fine", "Fine");
         s.claim(true, "ok");
         return s;
       }}};
  const std::vector<ValidationSection> out = runValidationItems(ctx, items);
  ASSERT_EQ(out.size(), 2u);
  ASSERT_EQ(out[0].claims().size(), 1u);
  EXPECT_EQ(out[0].claims()[0].verdict, Verdict::Fails);
  EXPECT_TRUE(contains(out[0].claims()[0].text, "no such scene"));
  EXPECT_EQ(countClaims(out[1].claims()).holds, 1);
}

// The energy-balanced drive paper: the integration-scheme claim decides by running the scheme at
// the step that closes the gap of the first point over the whole table.
PaperSweep flywheelSweep(double fitted_delta_at_large) {
  PaperSweep p;
  p.id = "energy_balanced";
  p.fitted_step_deg = 10.7;
  auto pt = [](double x, double ours, double baranov, double published, double fitted) {
    SweepPoint s;
    s.x = x;
    s.reduced.complete = s.reduced.rotating = true;
    s.reduced.delta = ours;
    s.variant = s.reduced;
    s.variant.delta = baranov;
    s.has_variant = s.has_published = s.has_fitted = true;
    s.published["delta"] = published;
    s.fitted = s.reduced;
    s.fitted.delta = fitted;
    return s;
  };
  p.points = {pt(0, 0.0964, 0.0976, 0.11, 0.1105), pt(1000, 0.0141, 0.0141, 0.0117, fitted_delta_at_large)};
  return p;
}

TEST(PaperFindings, SchemeIsNotTheCauseOnlyIfItsFittedStepLeavesTheGap) {
  const Scene sc = test_scenes::loveikin2018Scene();
  auto scheme = [](const std::vector<Finding>& f) { return findingStarting(f, "Integration scheme"); };
  // At the fitted step the large-flywheel point keeps its +22 % gap: not the cause, holds.
  auto f = findingsEnergyBalanced(flywheelSweep(0.0143), {}, sc);
  ASSERT_NE(scheme(f), nullptr);
  EXPECT_EQ(scheme(f)->verdict, Verdict::Holds) << scheme(f)->text;
  EXPECT_TRUE(contains(scheme(f)->text, "h* = 10.7°")) << scheme(f)->text;
  // Had the fitted step closed the gap there too (δ = 0.0118 against 0.0117), the scheme would
  // explain the table: the claim fails.
  f = findingsEnergyBalanced(flywheelSweep(0.0118), {}, sc);
  EXPECT_EQ(scheme(f)->verdict, Verdict::Fails) << scheme(f)->text;
  EXPECT_EQ(f.front().verdict, Verdict::Fails) << "a gap whose reason fails is not explained";
}

// Section (5), the induction-motor claims, goes through the same counting: a motor claim that
// fails is a FAILED claim of the report (summary, results.json, exit status 1), and the validation
// items are numbered after it.
TEST(ValidationReport, MotorClaimsAreCountedAndDecideTheExitStatus) {
  ValidationResults r;
  r.equivalence = {comparison("E0", 1e-9, 3e-8, 2e-7, true)};
  MotorClaim m1{"M1", "a motor law against its reference", {"numbers 1.0 against 1.0"}, Verdict::Holds};
  MotorClaim m2{"M2", "another motor law", {"numbers 2.0 against 1.0"}, Verdict::Holds};
  r.motor = {m1, m2};
  ValidationSection item("extra", "An item of its own");
  item.claim(true, "a comparison that held");
  r.sections = {item};
  ValidationReport rep = buildValidationReport(r, "figures");
  EXPECT_EQ(countClaims(rep.claims).holds, 3);
  EXPECT_EQ(validationExitStatus(r, rep), 0);
  EXPECT_TRUE(contains(rep.markdown, "## (5) The induction-motor laws"));
  EXPECT_TRUE(contains(rep.markdown, "## (6) An item of its own"));

  r.motor[1].verdict = Verdict::Fails;
  rep = buildValidationReport(r, "figures");
  EXPECT_EQ(countClaims(rep.claims).failed, 1);
  EXPECT_EQ(validationExitStatus(r, rep), 1);
  EXPECT_TRUE(contains(validationSummary(r, rep), "FAILED M2")) << validationSummary(r, rep);
  EXPECT_TRUE(contains(rep.markdown, "- **M2** another motor law: **FAILED**"));
  EXPECT_EQ(rep.results["claim_count"]["failed"], 1);
}

TEST(ValidationReport, CartsOfTheirOwnPrintTheirVerdicts) {
  ValidationResults r;
  ComparisonCase held = comparison("P1", 1e-11, 3e-10, 2e-9, true);
  held.explanation = "Claim (a) ... Claim (b): order 1 rises.";
  held.verdict = Finding::Verdict::Holds;
  ComparisonCase failed = comparison("P2", 1e-11, 3e-10, 2e-9, false);
  failed.explanation = "Claim (b): order 2 stays in the noise.";
  failed.verdict = Finding::Verdict::Fails;
  failed.measured = {{"coupling torque order 2 multibody / reduced / uniform scene [N·m]", "1 / 1 / 0.5"}};
  r.per_cart = {held, failed};
  const ValidationReport rep = buildValidationReport(r, "figures");
  EXPECT_TRUE(contains(rep.markdown, "### Carts of their own"));
  EXPECT_TRUE(contains(rep.markdown, "Claim (b): order 1 rises. **holds**"));
  EXPECT_TRUE(contains(rep.markdown, "Claim (b): order 2 stays in the noise. **FAILED**"));
  EXPECT_TRUE(contains(rep.markdown, "uniform scene [N·m]: 1 / 1 / 0.5"));
  ASSERT_EQ(rep.results["per_cart"].size(), 2u);
  EXPECT_EQ(rep.results["per_cart"][0]["verdict"], "holds");
  EXPECT_EQ(rep.results["per_cart"][1]["verdict"], "failed");
  // Both cases are claims of the report: the failed one is counted and makes validate exit 1.
  EXPECT_EQ(countClaims(rep.claims).holds, 1);
  EXPECT_EQ(countClaims(rep.claims).failed, 1);
  EXPECT_EQ(validationExitStatus(r, rep), 1);
  EXPECT_TRUE(contains(validationSummary(r, rep), "FAILED P2")) << validationSummary(r, rep);
}

}  // namespace
}  // namespace rollerdyn::validation
