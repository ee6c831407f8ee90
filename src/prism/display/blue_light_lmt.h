#pragma once
// The Academy's blue-light-artifact fix LMT (aces-dev lmt/LMT.Academy.BlueLightArtifactFix.ctl,
// ACES 1.1): a 3×3 in ACES2065-1 that pulls very saturated blues, which the RRT renders
// as magenta/cyan artefacts, back towards the hue of nearby less saturated blues. A
// strength in [0, 1] blends the matrix with identity, as Unreal Engine's "Blue Correction".
#include "prism/core/mat3.h"
#include "prism/core/vec.h"

namespace prism::display {

// The LMT's correctionMatrix, for column vectors (ACES2065-1 → ACES2065-1).
const Mat3& blue_light_artifact_fix_matrix();

// (1 − strength)·I + strength·M. Strength outside [0, 1] or NaN: UsageError.
Mat3 blue_correction_matrix(double strength);

}  // namespace prism::display
