#pragma once
// CIE 1976 L*a*b* (CIE 15:2004 §8.2.1) and the CIE76 colour difference ΔE*ab.
#include "prism/core/vec.h"

namespace prism::color {

// L*, a*, b* of `xyz` relative to the reference white `white_xyz` (same scale).
Vec3d xyz_to_lab(const Vec3d& xyz, const Vec3d& white_xyz);

// Euclidean distance in L*a*b* (ΔE*ab, CIE 1976). One unit is roughly a just-noticeable
// difference for side-by-side patches.
inline double delta_e76(const Vec3d& lab1, const Vec3d& lab2) { return length(lab1 - lab2); }

}  // namespace prism::color
