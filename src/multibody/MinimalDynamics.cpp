#include "multibody/MinimalDynamics.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "multibody/GuideFriction.h"
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

// A cart's normals in the loop's affine form N = n0 + n_eps·ε + n_F·F from those at ε0 (n0),
// per unit ε (ne) and per unit friction (nf) [N, N·s²/rad, N/N].
void setAffineNormals(const GuideNormals& n0, const GuideNormals& ne, const GuideNormals& nf, double eps0,
                      GuideLoopCart& t) {
  // n0 holds the normals at ε0: shift to ε = 0 for the loop's affine form.
  t.n0[0] = n0.front - ne.front * eps0;
  t.n0[1] = n0.rear - ne.rear * eps0;
  t.n_eps[0] = ne.front;
  t.n_eps[1] = ne.rear;
  t.n_F[0] = nf.front;
  t.n_F[1] = nf.rear;
}

}  // namespace

MinimalDynamics::MinimalDynamics(const MultibodyModel& model, const SimTK::State& s)
    : model_(model), k_crank_(model.options().prescribe_crank_speed ? -1 : 0) {
  udot_.resize(s.getNU());
  residual_.resize(s.getNU());
  const SimTK::SimbodyMatterSubsystem& matter = model.matter();
  f_body_.resize(matter.getNumBodies());
  f_particle_.resize(matter.getNumParticles());
  f_mobility_.resize(s.getNU());
  const int n = int(model.carts().size());
  q_crank_ = model.crank().getFirstQIndex(s);
  for (const CartRig& c : model.carts()) carts_.push_back(cartDataOf(c, s));
  loop_carts_.resize(n);
  loop_friction_.resize(n);
  loop_normals_.resize(2 * n);
}

MinimalDynamics::CartData MinimalDynamics::cartDataOf(const CartRig& c, const SimTK::State& s) {
  CartData d;
  d.q_cart = c.cart.getFirstQIndex(s);
  d.u_cart = c.cart.getFirstUIndex(s);
  d.u_rod = c.rod.isEmptyHandle() ? -1 : int(c.rod.getFirstUIndex(s));
  d.body = c.cart.getMobilizedBodyIndex();
  d.side = c.side;
  d.cam = !c.cam.isEmptyHandle();
  d.massless_rod = !d.cam && c.rod.isEmptyHandle();
  d.mass = c.cart.getBodyMass(s);
  d.p_com = c.cart.getBodyMassCenterStation(s);
  d.p_pin = c.p_CrankPin;
  return d;
}

bool MinimalDynamics::evaluate(SimTK::State& s, const MinimalCoordinates& coords) {
  const bool algebraic = model_.hasGuideFriction() && !model_.frictionElement().lagged();
  return evaluateImpl(s, coords, algebraic, algebraic);
}

bool MinimalDynamics::evaluateWithLoop(SimTK::State& s, const MinimalCoordinates& coords) {
  return evaluateImpl(s, coords, model_.hasGuideFriction(), false);
}

bool MinimalDynamics::evaluateImpl(SimTK::State& s, const MinimalCoordinates& coords, bool solve_loop,
                                   bool keep_normals) {
  // With the loop solved here, the friction is added once it is known.
  solveProjected(s, coords, /*include_friction=*/!solve_loop);
  loop_ = GuideLoopResult{};
  placeLoops(s);
  if (!solve_loop) return true;
  const double eps0 = k_crank_ >= 0 ? nu_dot_(k_crank_) : 0.0;
  setUpFrictionLoop(s, coords, eps0);
  loop_ = solveGuideFrictionLoop(loop_carts_.data(), int(carts_.size()), eps0, loop_friction_.data(),
                                 &loop_normals_[0]);
  if (loop_.status != LoopStatus::Solved) return false;
  applyLoopFriction(coords);
  if (keep_normals) model_.frictionElement().setNormalsInUse(s, loop_normals_);
  return true;
}

// inline (with the next): solveProjected's steps in every evaluation of the right-hand side.
inline void MinimalDynamics::residualAtBias(SimTK::State& s, const MinimalCoordinates& coords, bool include_friction) {
  const SimTK::MultibodySystem& system = model_.system();
  const SimTK::SimbodyMatterSubsystem& matter = model_.matter();
  // The inverse-dynamics pass and M·v need positions and velocities only (Simbody's tree
  // position and velocity caches); the applied forces f are summed directly, which costs less
  // than Simbody's generic realization of the Dynamics stage.
  system.realize(s, SimTK::Stage::Velocity);
  f_body_.setToZero();
  f_particle_.setToZero();
  f_mobility_.setToZero();
  model_.addAppliedForces(s, f_body_, f_particle_, f_mobility_, include_friction);
  // r0 = M·(Ṅ·ν̇) + c - f
  matter.calcResidualForceIgnoringConstraints(s, f_mobility_, f_body_, coords.bias(), residual_);
  const int k = coords.freeSpeeds();
  for (int i = 0; i < k; ++i) matter.multiplyByM(s, coords.column(i), mn_[i]);
}

inline void MinimalDynamics::solveIndependentAccelerations(const MinimalCoordinates& coords,
                                                           const Eigen::Map<Eigen::VectorXd>& residual) {
  const int k = coords.freeSpeeds();
  Eigen::Matrix2d A = Eigen::Matrix2d::Identity();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (int i = 0; i < k; ++i) {
    const Eigen::Map<const Eigen::VectorXd> n_i = view(coords.column(i));
    b(i) = -n_i.dot(residual);
    for (int j = 0; j < k; ++j) A(i, j) = n_i.dot(view(mn_[j]));
  }
  A_inv_.setZero();
  if (k == 1) A_inv_(0, 0) = 1.0 / A(0, 0);
  if (k == 2) A_inv_ = A.inverse();
  nu_dot_.setZero();
  if (k == 1) nu_dot_(0) = b(0) / A(0, 0);
  if (k == 2) nu_dot_ = A.partialPivLu().solve(b);
}

void MinimalDynamics::solveProjected(SimTK::State& s, const MinimalCoordinates& coords, bool include_friction) {
  residualAtBias(s, coords, include_friction);
  const int k = coords.freeSpeeds();
  // The small products by Eigen on the Simbody vectors' storage: SimTK's Vector expressions
  // allocate a temporary per term (~15 % of an evaluation at 4 carts).
  const Eigen::Map<const Eigen::VectorXd> bias = view(coords.bias());
  Eigen::Map<Eigen::VectorXd> residual = view(residual_), udot = view(udot_);
  solveIndependentAccelerations(coords, residual);
  udot = bias;
  for (int i = 0; i < k; ++i) {
    udot += nu_dot_(i) * view(coords.column(i));
    residual += nu_dot_(i) * view(mn_[i]);  // now the generalized constraint forces M·u̇ + c - f
  }
}

// The friction loop (GuideFrictionLoop.h). Everything solveProjected computes is linear in the
// cart frictions F_j (world x, applied at the guide contacts d/2 above B): F_j adds F_j to cart
// j's generalized applied force, so it lowers that constraint force by F_j, adds column_i(cart)·F_j
// to b_i and the moment -(d/2)·F_j about B to the cart's applied forces. Along ν̈ only the crank
// column moves the carts and rods (the motor side, the twist column, is no ancestor of either),
// so a cart's normal forces depend on ν̈ through ε alone.
void MinimalDynamics::setUpFrictionLoop(const SimTK::State& s, const MinimalCoordinates& coords, double eps0) {
  const GuideFriction& friction = model_.frictionElement();
  const int n = int(carts_.size());
  const double half_d = 0.5 * model_.scene().carts.geometry.d;
  const SimTK::SpatialVec unit_friction(SimTK::Vec3(0, 0, -half_d), SimTK::Vec3(1, 0, 0));
  const SimTK::SpatialVec none(SimTK::Vec3(0), SimTK::Vec3(0));
  const SimTK::Vector* crank_column = k_crank_ >= 0 ? &coords.column(k_crank_) : nullptr;
  const SimTK::Vector* crank_mn = k_crank_ >= 0 ? &mn_[k_crank_] : nullptr;
  const SimTK::Vector& u = s.getU();
  for (int j = 0; j < n; ++j) {
    const CartData& c = carts_[j];
    const int uc = c.u_cart, ur = c.u_rod;
    GuideLoopCart& t = loop_carts_[j];
    const GuideNormals n0 = cartNormals(j, residual_[uc], ur >= 0 ? residual_[ur] : 0.0, udot_[uc], f_body_[c.body]);
    GuideNormals ne{0, 0};
    if (crank_column)
      ne = cartNormals(j, (*crank_mn)[uc], ur >= 0 ? (*crank_mn)[ur] : 0.0, (*crank_column)[uc], none);
    setAffineNormals(n0, ne, cartNormals(j, -1.0, 0.0, 0.0, unit_friction), eps0, t);
    t.c = friction.frictionPerNormal(j, u[uc]);
    t.w = crank_column ? A_inv_(k_crank_, k_crank_) * (*crank_column)[uc] : 0.0;
  }
}

void MinimalDynamics::applyLoopFriction(const MinimalCoordinates& coords) {
  const int k = coords.freeSpeeds();
  const double half_d = 0.5 * model_.scene().carts.geometry.d;
  const SimTK::SpatialVec unit_friction(SimTK::Vec3(0, 0, -half_d), SimTK::Vec3(1, 0, 0));
  Eigen::Map<Eigen::VectorXd> residual = view(residual_), udot = view(udot_);
  Eigen::Vector2d db = Eigen::Vector2d::Zero();
  for (std::size_t j = 0; j < carts_.size(); ++j) {
    const CartData& c = carts_[j];
    const int uc = c.u_cart;
    for (int i = 0; i < k; ++i) db(i) += coords.column(i)[uc] * loop_friction_[j];
    residual_[uc] -= loop_friction_[j];
    // The friction's spatial force on the cart (GuideFriction::calcForce applies the same at the
    // two guide contacts, both d/2 above B): force F, moment -(d/2)·F about B.
    f_body_[c.body] += loop_friction_[j] * unit_friction;
  }
  const Eigen::Vector2d dnu = A_inv_ * db;
  for (int i = 0; i < k; ++i) {
    nu_dot_(i) += dnu(i);
    udot += dnu(i) * view(coords.column(i));
    residual += dnu(i) * view(mn_[i]);
  }
}

void MinimalDynamics::placeLoops(const SimTK::State& s) {
  const SimTK::Vector& q = s.getQ();
  const double phi = q[q_crank_], cp = std::cos(phi), sp = std::sin(phi);
  for (CartData& c : carts_) {
    if (c.cam) continue;
    // A = R_z(φ2)·p_pin (the crankshaft turns about ground z through the origin), B = (x_B, 0).
    const double Ax = cp * c.p_pin[0] - sp * c.p_pin[1], Ay = sp * c.p_pin[0] + cp * c.p_pin[1];
    c.r_AB = SimTK::Vec3(q[c.q_cart] - Ax, -Ay, 0.0);
  }
}

double MinimalDynamics::loopForceY(int j, double Fx, double r_rod) const {
  const CartData& c = carts_[j];
  if (c.cam) return 0.0;  // cam drive: the pusher force is horizontal
  const SimTK::Vec3& r_AB = c.r_AB;
  if (c.massless_rod) return Fx * r_AB[1] / r_AB[0];  // a massless rod pushes along itself
  // The rod's pin mobility carries the z moment about A of the loop force on the rod, -F:
  // r_rod = -(r_AB × F)_z.
  return (r_AB[1] * Fx - r_rod) / r_AB[0];
}

GuideNormals MinimalDynamics::cartNormals(int j, double Fx, double r_rod, double a,
                                          const SimTK::SpatialVec& applied) const {
  const CartData& c = carts_[j];
  const double Fy = loopForceY(j, Fx, r_rod);
  // The cart only translates: Σ forces = m·a, Σ moments about B = p_BC × m·a; the loop force
  // acts at B. The slider joint supplies the rest (GuideReactions.h).
  const SimTK::Vec3 ma(c.mass * a, 0, 0);
  const SimTK::SpatialVec reaction(SimTK::cross(c.p_com, ma) - applied[0], ma - applied[1] - SimTK::Vec3(Fx, Fy, 0));
  return solveGuideNormals(reaction, c.side, model_.scene().carts.geometry);
}

SimTK::Vec2 MinimalDynamics::loopForce(const SimTK::State&, int j) const {
  const CartData& c = carts_[j];
  // Its x component is the cart's generalized constraint force; its y component depends on the loop.
  const double Fx = residual_[c.u_cart];
  const double r_rod = c.u_rod >= 0 ? residual_[c.u_rod] : 0.0;
  return SimTK::Vec2(Fx, loopForceY(j, Fx, r_rod));
}

SimTK::Vector MinimalDynamics::guideNormals(const SimTK::State&) const {
  SimTK::Vector n(2 * int(carts_.size()));
  for (size_t j = 0; j < carts_.size(); ++j) {
    const CartData& c = carts_[j];
    const GuideNormals g = cartNormals(int(j), residual_[c.u_cart], c.u_rod >= 0 ? residual_[c.u_rod] : 0.0,
                                       udot_[c.u_cart], f_body_[c.body]);
    n[2 * int(j)] = g.front;
    n[2 * int(j) + 1] = g.rear;
  }
  return n;
}

}  // namespace rollerdyn
