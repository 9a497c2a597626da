// Internals of the validation suite shared by its source files (ValidationSuite.cpp: the
// runner, equivalence and analytic sections; ValidationDifferences.cpp: where the physics differ;
// ValidationPapers.cpp: the papers' sweeps and the sensitivity table). Not a public header.
#pragma once

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "compare/ValidationSuite.h"
#include "multibody/MultibodySimulation.h"
#include "reduced/ReducedModel.h"
#include "scene/SceneParser.h"
#include "io/FieldFormat.h"

namespace rollerdyn::validation::detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline std::string g(double v, int prec = 3) { return significant(v, prec); }

// A value for --set that round-trips exactly.
inline std::string exact(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

inline std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Settings that make the two models' physics identical: the papers' split rods, no guide
// friction, exact kinematics, CVODE, and tight accuracy for both.
inline const std::vector<std::string> kEquivalentPhysics = {
    "rods.model=split", "loads.guide_friction.coefficient=0", "reduced.kinematics=exact",
    "reduced.integrator=cvode"};

class Suite {
 public:
  explicit Suite(const ValidationOptions& o) : o_(o) {}

  ValidationResults run();

 private:
  void log(const std::string& line) const {
    if (o_.log) o_.log(line);
  }
  bool interrupted() const { return o_.interrupt && o_.interrupt->load(); }
  // Every scene of the suite is read with the papers' setting for the reduced model's guide
  // normal forces (quasi-static, Loveikin, Pochka, Romasevych (2018) eq. (14)-(25)): the suite
  // reproduces and explains the papers, and its differences section measures what that setting
  // changes (docs/friction-and-reactions.md shows the kinetostatic default agreeing with the
  // multibody model). First, so that a case's own --set can override it; every printed command
  // carries it.
  static constexpr const char* kPapersNormals = "reduced.guide_normals=quasi_static";
  Scene load(const std::string& file, const std::vector<std::string>& sets) const {
    std::vector<std::string> all = {kPapersNormals};
    all.insert(all.end(), sets.begin(), sets.end());
    return parseSceneFile(o_.model_dir + "/" + file, all);
  }
  static std::string command(const std::string& verb, const std::string& file,
                             const std::vector<std::string>& sets) {
    std::string c = "rollerdyn " + verb + " model/" + file + " --set " + kPapersNormals;
    for (const auto& s : sets) c += " --set " + s;
    return c;
  }
  double timeForRevolutions(const std::string& file, const std::vector<std::string>& sets, double revs) const;
  ComparisonCase compareCase(const std::string& label, const std::string& description, const std::string& file,
                             const std::vector<std::string>& sets, double revs, ModelComparison* keep);
  void runCase(ComparisonCase& cc, const std::string& file, std::vector<std::string> sets, double revs,
               ModelComparison* keep);
  RunMetrics reducedMetrics(const std::string& file, const std::vector<std::string>& sets) const {
    const Scene sc = load(file, sets);
    return runMetrics(sc, runReducedModel(sc));
  }
  RunMetrics multibodyMetrics(const std::string& file, const std::vector<std::string>& sets) const {
    const Scene sc = load(file, sets);
    RunControl rc;
    rc.interrupt = o_.interrupt;
    return runMetrics(sc, runMultibodyModel(sc, rc));
  }

  SweepPoint paperPoint(const PaperSweep& p, const std::vector<std::string>& sets,
                        const std::vector<std::string>& variant, const std::string& multibody_log) const;
  bool sweepPaper(PaperSweep& p, const std::vector<double>& xs, const std::vector<double>& multibody_at,
                  const std::string& published_key, const std::function<std::string(double)>& describe);

  // Crank revolutions of each equivalence and per-cart run.
  double revolutions() const { return o_.quick ? 5 : 20; }
  void equivalence(ValidationResults& r);
 public:  // named by the functions of ValidationSuite.cpp
  struct EquivalenceSpec;

 private:
  void equivalenceE0(ValidationResults& r);
  bool equivalenceCases(ValidationResults& r, const std::vector<EquivalenceSpec>& specs);
  void convergence(ValidationResults& r, const std::vector<EquivalenceSpec>& specs);
  void perCart(ValidationResults& r);
 public:  // named by the functions of ValidationPerCart.cpp
  struct PerCartSpec;
  struct PerCartOrders;

 private:
  ComparisonCase perCartCase(const PerCartSpec& s, const std::vector<std::string>& base);
  PerCartOrders perCartOrders(const ModelComparison& c, double t_end, const PerCartSpec& s,
                              const std::vector<std::string>& base) const;
  void differences(ValidationResults& r);
  // Crank revolutions of each run of section (2) (D6-D8: the scene's own t_end).
  double differenceRevolutions() const { return o_.quick ? 3 : 10; }
  ComparisonCase distributedRodsDifference(ValidationResults& r);
  ComparisonCase frictionDifference(ValidationResults& r);
  ComparisonCase truncatedKinematicsDifference();
  ComparisonCase baranovDifference();
  // A shipped scene as it is in both models, with the claim that explains their difference.
  ComparisonCase shippedSceneDifference(const char* label, const char* file, const char* description,
                                        const std::vector<ComparisonCase>& earlier);
  void papersSection(ValidationResults& r);
  ItemContext itemContext() const;
  void papers(ValidationResults& r);
  // One paper's sweep each, described and run into `p`; false when interrupted (p incomplete).
  bool loveikin2007Sweep(PaperSweep& p);
  bool energyBalancedSweep(PaperSweep& p);
  bool fittedBaranovStep(PaperSweep& p);
  bool loveikin2018Sweep(PaperSweep& p);
  bool loveikin2018Points(PaperSweep& p);
  bool otherReadingPoints(PaperSweep& p);
  void sensitivity(ValidationResults& r);
  // The point of a paper where the sensitivity table changes one input at a time.
  struct SensitivityPoint {
    std::string paper, point, file;
    std::vector<std::string> base;  // --set values of the point as the scene ships
    std::string metric;
    double published;
    double RunMetrics::*field;
  };
  void sensitivityRow(ValidationResults& r, const SensitivityPoint& at, const std::string& change_label,
                      const std::vector<std::string>& change) const;
  void sensitivityLoveikin2007(ValidationResults& r) const;
  void sensitivityEnergyBalanced(ValidationResults& r) const;
  void sensitivityLoveikin2018(ValidationResults& r) const;
  void findings(ValidationResults& r);
  void analytic(ValidationResults& r);

  const ValidationOptions& o_;
};

}  // namespace rollerdyn::validation::detail
