// The spinning-ball model: ball–ball contact with Coulomb friction (throw) and a ball on the cloth
// (sliding, rolling, spinning), derived from Newton's and Euler's laws, and the kernels emitted from it.
#pragma once

#include "model.hpp"

namespace billiards::derive::spinning {

/// Runs every step, checks every claim and builds the kernels (validated later, by the pipeline).
Derivation derive();

/// Title, citation, scope, notation, remarks and the output paths.
ModelInfo info();

}  // namespace billiards::derive::spinning
