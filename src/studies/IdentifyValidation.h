// Validation item of the identification (`rollerdyn identify`, Identify.h): known values back
// from measurements the model makes itself with Gaussian noise (SyntheticMeasurements.h).
#pragma once

#include "compare/ValidationItems.h"

namespace rollerdyn::validation {

// (1) The case: a start of the default scene with the catalogue motor's equivalent
// circuit, coupling stiffness and damping other than the scene's, crank speed, motor speed and
// stator current measured with 0.2 % noise (multibody model): both values back within 3σ and 10 %
// from the scene's values. (2) Coverage: over 50 noise seeds (10 with --quick) the 2σ interval of
// each key holds its true value as often as a Gaussian estimate's should (IdentifyValidation.cpp).
ValidationSection identificationChecks(const ItemContext& ctx);

}  // namespace rollerdyn::validation
