// The shot model: what a cue strike gives the ball (the instantaneous point model of Alciatore's TP
// A-30, with the tip's restitution), derived from the impulse equations of the cue and the ball.
#pragma once

#include "model.hpp"

namespace billiards::derive::shot {

/// Runs every step and checks every claim.
Derivation derive();

/// Title, citation, scope, notation, remarks and the output paths.
ModelInfo info();

}  // namespace billiards::derive::shot
