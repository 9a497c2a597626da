// Simbody integrators by the names used in scene files (simulation.integrator).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "Simbody.h"

namespace rollerdyn {

// The integrator names rollerdyn accepts, in the order `bench` runs them.
const std::vector<std::string>& integratorNames();

// A new integrator for `system`, with accuracy and constraint tolerance set and its internal
// step limit raised (CPodes otherwise stops with mxstep errors on long output intervals).
// Throws std::invalid_argument listing the accepted names for an unknown name.
std::unique_ptr<SimTK::Integrator> makeIntegrator(const std::string& name, const SimTK::System& system,
                                                  double accuracy, double constraint_tolerance);

}  // namespace rollerdyn
