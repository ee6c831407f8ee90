#pragma once
// A dielectric material's index of refraction as a function of wavelength, from its
// dispersion model (Material::dispersion): what the renderer refracts with and what the
// scene writers turn into each format's terms.
#include "prism/bsdf/ior.h"
#include "prism/scene/material.h"

namespace prism {

// η of a dielectric material at one wavelength: its dispersion model's, or the constant
// Material::ior without one.
double dielectric_ior(const Material& m, double wavelength_nm);

// Makes the material's dispersion the two-term Cauchy glass `glass` (its coefficients held
// in float); Material::ior, its n_d, is the caller's to set.
void set_cauchy_dispersion(Material& m, const bsdf::CauchyIor& glass);

// The material's Abbe number V_d = (n_d − 1)/(n_F − n_C) (bsdf/ior.h), +∞ without dispersion.
double dielectric_abbe_number(const Material& m);

}  // namespace prism
