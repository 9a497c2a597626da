#include "studies/SyntheticMeasurements.h"

#include <cmath>

#include "compare/RunModel.h"
#include "scene/SceneParser.h"
#include "scene/SceneSchema.h"

namespace rollerdyn {

std::uint64_t GaussianNoise::bits() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double GaussianNoise::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double u1 = (static_cast<double>(bits() >> 11) + 0.5) * 0x1.0p-53;  // in (0, 1)
  const double u2 = static_cast<double>(bits() >> 11) * 0x1.0p-53;
  const double r = std::sqrt(-2.0 * std::log(u1));
  spare_ = r * std::sin(2.0 * M_PI * u2);
  has_spare_ = true;
  return r * std::cos(2.0 * M_PI * u2);
}

RunResult truthRun(const std::string& scene, std::vector<std::string> truth, double t_end, double step,
                   const std::string& model) {
  truth.push_back("simulation.t_end=" + formatNumber(t_end));
  truth.push_back("simulation.output_step=" + formatNumber(step));
  truth.push_back("simulation.accuracy=1e-10");
  const Scene s = parseSceneFile(scene, truth);
  return runModel(s, model);
}

MeasuredData measureRun(const RunResult& run, const std::vector<std::string>& columns, double noise_fraction,
                        std::uint64_t seed) {
  MeasuredData d;
  d.file = "synthetic measurements";
  d.t = run.timeseries.column("t");
  for (std::size_t i = 0; i < d.t.size(); ++i) d.lines.push_back(static_cast<int>(i) + 2);
  GaussianNoise noise(seed);
  for (const std::string& c : columns) {
    MeasuredSignal s;
    s.name = c;
    s.unit = columnUnit(c);
    s.values = run.timeseries.column(c);
    double rms = 0;
    for (double v : s.values) rms += v * v;
    rms = std::sqrt(rms / static_cast<double>(s.values.size()));
    for (double& v : s.values) v += noise_fraction * rms * noise.next();
    d.signals.push_back(s);
  }
  return d;
}

std::vector<std::string> couplingCaseTruth(std::vector<std::string> sets) {
  sets.push_back("coupling.stiffness=" + formatNumber(kCouplingCaseStiffness));
  sets.push_back("coupling.damping=" + formatNumber(kCouplingCaseDamping));
  return sets;
}

IdentifyOptions couplingCaseFit(const std::string& scene_path, const std::string& model, std::vector<std::string> sets) {
  IdentifyOptions o;
  o.scene_path = scene_path;
  o.base_overrides = std::move(sets);
  o.model = model;
  o.free_keys = {"coupling.stiffness", "coupling.damping"};
  o.bounds = {{"coupling.stiffness", {2e4, 2e6}}, {"coupling.damping", {500, 50000}}};
  return o;
}

}  // namespace rollerdyn
