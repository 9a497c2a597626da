// The bodies and points of one crank-slider in the built Simbody system, and where on the cart
// the loads act (Loveikin, Pochka, Romasevych (2018) fig. 3, eq. (10)). The cart frame keeps the ground orientation (the
// cart only slides), its origin is the rod hinge B, so a station on the cart is also the
// world-frame offset from B. σ = side mirrors every x offset for a cart on the -x side.
#pragma once

#include "Simbody.h"
#include "scene/Scene.h"

namespace rollerdyn {

struct CartRig {
  int side = 1;                  // σ: +1 cart on the +x side of the shaft, -1 on the -x side
  SimTK::MobilizedBody cart;     // slider along ground x, origin at hinge B
  SimTK::MobilizedBody crank;    // the crankshaft body its crank pin is on: the crankshaft, or its
                                 // throw of a torsional chain (crankshaft.torsional_stiffness)
  SimTK::MobilizedBody rod;      // rod body (distributed model only; otherwise invalid handle)
  SimTK::Constraint cam;         // cam drive (Loveikin and Pochka (cam drive paper)): coupler x_B = σ·x(θ); else empty handle
  SimTK::Vec3 p_CrankPin;        // crank pin A in the crankshaft frame [m]
  double rod_mass = 0;           // mass of the rod body (0 unless distributed) [kg]
  double rod_length = 0;         // l [m]

  // Contact points of the compacting rollers (front = nearer B, at p - a; rear at p + a), depth e.
  SimTK::Vec3 rollerFront(const CartGeometry& g) const { return {side * (g.p - g.a), -g.e, 0}; }
  SimTK::Vec3 rollerRear(const CartGeometry& g) const { return {side * (g.p + g.a), -g.e, 0}; }
  // Contact points of the guide rollers with the guide: d/2 above their axles at B's height
  // (eq. (10)'s friction moment -(N1 + N2)·f·d/2).
  SimTK::Vec3 guideFront(const CartGeometry& g) const { return {side * (g.p - g.b), 0.5 * g.d, 0}; }
  SimTK::Vec3 guideRear(const CartGeometry& g) const { return {side * (g.p + g.b), 0.5 * g.d, 0}; }

  double x(const SimTK::State& s) const { return cart.getOneQ(s, 0); }
  double v(const SimTK::State& s) const { return cart.getOneU(s, 0); }
};

}  // namespace rollerdyn
