// The model of S. T. Parkin, "Billiard Ball Physics" (2023): the paper re-derived step by step from
// its definitions, the physics engines need beyond it, and the kernels emitted from both.
#pragma once

#include "model.hpp"

#include <ginac/ginac.h>

namespace billiards::derive::parkin2023 {

/// The paper's definitions, P(a, b) = m1 a + m2 b and K(a, b) = ½ m1 a² + ½ m2 b², and the quadratic
/// formula's discriminant, written as the coefficients of each term so that a test can perturb one and
/// watch the claims downstream fail.
struct Definitions {
  GiNaC::ex momentum_coefficient_1 = 1;
  GiNaC::ex momentum_coefficient_2 = 1;
  GiNaC::ex kinetic_coefficient_1 = GiNaC::numeric(1, 2);
  GiNaC::ex kinetic_coefficient_2 = GiNaC::numeric(1, 2);
  /// The −4 of the discriminant B² − 4AC, so that a test can make the slip B² + 4AC.
  GiNaC::ex discriminant_ac_coefficient = -4;
};

/// Runs every step with the given definitions (the paper's by default), checks every claim and builds
/// the kernels (validated later, by the pipeline, before anything is printed).
Derivation derive(const Definitions& definitions = {});

/// Title, citation, scope, notation, the paper's imprecisions and the output paths.
ModelInfo info();

}  // namespace billiards::derive::parkin2023
