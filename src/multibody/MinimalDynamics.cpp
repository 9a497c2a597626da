#include "multibody/MinimalDynamics.h"

#include <stdexcept>

#include <Eigen/Dense>

#include "multibody/GuideReactions.h"

namespace rollerdyn {
namespace {

// A SimTK::Vector's elements as an Eigen vector (no copy); the Vectors here own contiguous storage.
Eigen::Map<const Eigen::VectorXd> view(const SimTK::Vector& v) {
  if (!v.hasContiguousData()) throw std::logic_error("MinimalDynamics: a vector without contiguous storage");
  return Eigen::Map<const Eigen::VectorXd>(v.size() ? &v[0] : nullptr, v.size());
}
Eigen::Map<Eigen::VectorXd> view(SimTK::Vector& v) {
  if (!v.hasContiguousData()) throw std::logic_error("MinimalDynamics: a vector without contiguous storage");
  return Eigen::Map<Eigen::VectorXd>(v.size() ? &v[0] : nullptr, v.size());
}

}  // namespace

MinimalDynamics::MinimalDynamics(const MultibodyModel& model, const SimTK::State& s) : model_(model) {
  udot_.resize(s.getNU());
  residual_.resize(s.getNU());
  const SimTK::SimbodyMatterSubsystem& matter = model.matter();
  f_body_.resize(matter.getNumBodies());
  f_particle_.resize(matter.getNumParticles());
  f_mobility_.resize(s.getNU());
}

void MinimalDynamics::evaluate(const SimTK::State& s, const MinimalCoordinates& coords) {
  const SimTK::MultibodySystem& system = model_.system();
  const SimTK::SimbodyMatterSubsystem& matter = model_.matter();
  // The inverse-dynamics pass and M·v need positions and velocities only (Simbody's tree
  // position and velocity caches); the applied forces f are summed directly, which costs less
  // than Simbody's generic realization of the Dynamics stage.
  system.realize(s, SimTK::Stage::Velocity);
  f_body_.setToZero();
  f_particle_.setToZero();
  f_mobility_.setToZero();
  model_.addAppliedForces(s, f_body_, f_particle_, f_mobility_);
  // r0 = M·(Ṅ·ν̇) + c - f
  matter.calcResidualForceIgnoringConstraints(s, f_mobility_, f_body_, coords.bias(), residual_);
  const int k = coords.freeSpeeds();
  for (int i = 0; i < k; ++i) matter.multiplyByM(s, coords.column(i), mn_[i]);
  // The small products by Eigen on the Simbody vectors' storage: SimTK's Vector expressions
  // allocate a temporary per term (~15 % of an evaluation at 4 carts).
  const Eigen::Map<const Eigen::VectorXd> bias = view(coords.bias());
  Eigen::Map<Eigen::VectorXd> residual = view(residual_), udot = view(udot_);
  Eigen::Matrix2d A = Eigen::Matrix2d::Identity();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (int i = 0; i < k; ++i) {
    const Eigen::Map<const Eigen::VectorXd> n_i = view(coords.column(i));
    b(i) = -n_i.dot(residual);
    for (int j = 0; j < k; ++j) A(i, j) = n_i.dot(view(mn_[j]));
  }
  nu_dot_.setZero();
  if (k == 1) nu_dot_(0) = b(0) / A(0, 0);
  if (k == 2) nu_dot_ = A.partialPivLu().solve(b);
  udot = bias;
  for (int i = 0; i < k; ++i) {
    udot += nu_dot_(i) * view(coords.column(i));
    residual += nu_dot_(i) * view(mn_[i]);  // now the generalized constraint forces M·u̇ + c - f
  }
}

SimTK::Vector MinimalDynamics::guideNormals(const SimTK::State& s) const {
  const std::vector<CartRig>& carts = model_.carts();
  const SimTK::Vector_<SimTK::SpatialVec>& f_body = f_body_;
  SimTK::Vector n(2 * int(carts.size()));
  for (size_t j = 0; j < carts.size(); ++j) {
    const CartRig& c = carts[j];
    // Loop force on the cart at its hinge B (ground axes): its x component is the cart's
    // generalized constraint force; its y component depends on the loop.
    const double Fx = residual_[c.cart.getFirstUIndex(s)];
    double Fy = 0.0;  // cam drive: the pusher force is horizontal
    if (c.cam.isEmptyHandle()) {
      const SimTK::Vec3 p_A = model_.crank().findStationLocationInGround(s, c.p_CrankPin);
      const SimTK::Vec3 r_AB = c.cart.getBodyOriginLocation(s) - p_A;
      if (c.rod.isEmptyHandle()) {
        Fy = Fx * r_AB[1] / r_AB[0];  // a massless rod pushes along itself
      } else {
        // The rod's pin mobility carries the z moment about A of the loop force on the rod,
        // -F: r_rod = -(r_AB × F)_z.
        const double r_rod = residual_[c.rod.getFirstUIndex(s)];
        Fy = (r_AB[1] * Fx - r_rod) / r_AB[0];
      }
    }
    // The cart only translates: Σ forces = m·a, Σ moments about B = p_BC × m·a; the loop force
    // acts at B. The slider joint supplies the rest (GuideReactions.h).
    const double m = c.cart.getBodyMass(s);
    const SimTK::Vec3 p_com = c.cart.getBodyMassCenterStation(s);
    const SimTK::Vec3 ma(m * udot_[c.cart.getFirstUIndex(s)], 0, 0);
    const SimTK::SpatialVec& applied = f_body[c.cart.getMobilizedBodyIndex()];
    const SimTK::SpatialVec reaction(SimTK::cross(p_com, ma) - applied[0], ma - applied[1] - SimTK::Vec3(Fx, Fy, 0));
    const GuideNormals g = solveGuideNormals(reaction, c.side, model_.scene().carts.geometry);
    n[2 * int(j)] = g.front;
    n[2 * int(j) + 1] = g.rear;
  }
  return n;
}

}  // namespace rollerdyn
