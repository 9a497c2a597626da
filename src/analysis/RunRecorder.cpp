#include "analysis/RunRecorder.h"

#include <utility>

#include "motor/Supply.h"
#include "scene/Scene.h"

namespace rollerdyn {

RunRecorder::RunRecorder(const Scene& scene, const Supply* supply, bool prescribed_crank_speed, RunResult& run,
                         const RunControl& control)
    : supply_(supply),
      run_(run),
      control_(control),
      t_end_(scene.simulation.t_end),
      stall_(scene.hasMotor(), scene.motor.omega_sync / scene.reducer.ratio),
      rest_(!scene.hasMotor() && !prescribed_crank_speed, scene.loads.velocity_smoothing) {}

bool RunRecorder::record(double t, std::vector<double> timeseries, std::vector<double>* reactions,
                         const RowMotion& motion) {
  const bool finite = rowIsFinite(timeseries) && (!reactions || rowIsFinite(*reactions));
  run_.timeseries.rows.push_back(std::move(timeseries));
  if (reactions) run_.reactions.rows.push_back(*reactions);
  return check(t, finite, motion);
}

bool RunRecorder::check(double t, bool row_finite, const RowMotion& motion) {
  if (!row_finite) return end(statusAt("numerical failure (non-finite value)", t));
  const bool full_supply = !motion.phase || Supply::fullSupply(*motion.phase);
  if (full_supply && stall_.update(t, motion.phi_crank, motion.omega_crank, motion.omega_motor))
    return end(stall_.status());
  if (supply_ && motion.phase && Supply::tripped(*motion.phase))
    return end(supply_->tripStatus(supply_->tripTime()));
  if (motion.cart_speeds && rest_.update(t, *motion.cart_speeds, int(motion.cart_speeds->size())))
    return end(rest_.status());
  if (initial_row_) {
    initial_row_ = false;
    return true;
  }
  if (control_.progress) control_.progress(t, t_end_);
  if (control_.interrupt && control_.interrupt->load()) return end(statusAt("interrupted", t));
  return true;
}

void RunRecorder::fail(std::string status) { end(std::move(status)); }

bool RunRecorder::end(std::string status) {
  run_.stats.complete = false;
  run_.stats.status = std::move(status);
  return false;
}

}  // namespace rollerdyn
