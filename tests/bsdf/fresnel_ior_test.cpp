#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "prism/bsdf/fresnel.h"
#include "prism/bsdf/ior.h"
#include "prism/core/error.h"

namespace prism::bsdf {
namespace {

TEST(Fresnel, DielectricNormalIncidenceAndSymmetry) {
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.5f), 0.04f, 1e-6f);   // ((η−1)/(η+1))²
  EXPECT_NEAR(fresnel_dielectric(-1.0f, 1.5f), 0.04f, 1e-6f);  // same from inside
  EXPECT_NEAR(fresnel_dielectric(0.0f, 1.5f), 1.0f, 1e-6f);    // grazing
  // Stokes reciprocity: the reflectance is the same from both sides at Snell-paired angles.
  for (float c : {0.9f, 0.5f, 0.2f}) {
    const float ct = refracted_cos_theta(c, 1.5f);
    EXPECT_NEAR(fresnel_dielectric(c, 1.5f), fresnel_dielectric(-ct, 1.5f), 1e-5f);
  }
  // Total internal reflection beyond the critical angle asin(1/1.5) = 41.8°.
  EXPECT_EQ(fresnel_dielectric(-std::cos(0.75f), 1.5f), 1.0f);
  EXPECT_LT(fresnel_dielectric(-std::cos(0.72f), 1.5f), 1.0f);
}

// R + T = 1 with T from the amplitude transmission coefficients (Born & Wolf §1.5.2),
// T = (η cos θt / cos θi) (t_s² + t_p²)/2: an independent energy balance.
TEST(Fresnel, DielectricConservesEnergy) {
  const float eta = 1.5f;
  for (float c : {1.0f, 0.8f, 0.5f, 0.1f}) {
    const float ct = refracted_cos_theta(c, eta);
    const float ts = 2 * c / (c + eta * ct), tp = 2 * c / (eta * c + ct);
    const float T = eta * ct / c * 0.5f * (ts * ts + tp * tp);
    EXPECT_NEAR(fresnel_dielectric(c, eta) + T, 1.0f, 1e-5f) << c;
  }
}

TEST(Fresnel, ConductorLimits) {
  // k = 0 reduces to the dielectric formula; normal incidence ((n−1)² + k²)/((n+1)² + k²).
  for (float c : {1.0f, 0.6f, 0.2f}) EXPECT_NEAR(fresnel_conductor(c, 1.5f, 0.0f), fresnel_dielectric(c, 1.5f), 1e-5f);
  const float n = 0.29f, k = 2.863f;  // gold near 582 nm
  EXPECT_NEAR(fresnel_conductor(1.0f, n, k), ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k), 1e-5f);
  EXPECT_NEAR(fresnel_conductor(0.0f, n, k), 1.0f, 1e-5f);
  EXPECT_NEAR(fresnel_schlick(0.3f, 1.0f), 0.3f, 1e-7f);
  EXPECT_NEAR(fresnel_schlick(0.3f, 0.0f), 1.0f, 1e-7f);
  color::SampledSpectrum<4> eta(1.5f), kk(0.0f);
  EXPECT_NEAR(fresnel_conductor(0.7f, eta, kk)[3], fresnel_dielectric(0.7f, 1.5f), 1e-5f);
}

// SCHOTT catalogue values for N-BK7: n_d = 1.51680 (587.56 nm), n_F = 1.52238 (486.13 nm),
// n_C = 1.51432 (656.27 nm), given to 5 decimals: a tolerance of 1e-5 covers their rounding
// (5e-6) plus SCHOTT's stated fit accuracy of the Sellmeier formula in the visible.
TEST(Dispersion, Bk7SellmeierMatchesCatalogue) {
  const SellmeierIor bk7 = sellmeier_bk7();
  EXPECT_NEAR(bk7(587.56), 1.51680, 1e-5);
  EXPECT_NEAR(bk7(486.13), 1.52238, 1e-5);
  EXPECT_NEAR(bk7(656.27), 1.51432, 1e-5);
  // Cauchy with n = A + B/λ²: exact at λ = 1 µm, and normal dispersion (n falls with λ).
  const CauchyIor cauchy{1.5046, 0.00420};
  EXPECT_NEAR(cauchy(1000.0), 1.5088, 1e-12);
  EXPECT_GT(cauchy(450.0), cauchy(650.0));
  color::SampledWavelengths<4> w;
  w.wavelength_nm = {450.0f, 500.0f, 550.0f, 650.0f};
  const auto eta = relative_ior(bk7, w);
  EXPECT_GT(eta[0], eta[3]);
  EXPECT_NEAR(eta[2], bk7(550.0), 1e-6);
}

// KHR_materials_dispersion's glass: the two-term Cauchy glass with index n_d at the d line
// and Abbe number V_d. Its closed form n_d + (n_d − 1)/V_d (523655/λ² − 1.5168) rounds the
// two constants (523655.09 and 1.516844): they move n by at most (n_d − 1)/V_d × (0.09/λ²
// + 4.4e-5), under (n_d − 1)/V_d × 5e-5 across 380–780 nm.
TEST(Dispersion, CauchyGlassOfAnAbbeNumberIsTheGltfOne) {
  for (const auto& [n_d, v_d] : {std::pair{1.5, 20.0}, {1.5168, 64.17}, {2.42, 55.0}, {1.33, 55.0}}) {
    const CauchyIor glass = CauchyIor::from_abbe_number(n_d, v_d);
    EXPECT_NEAR(glass(587.56), n_d, 1e-12);
    EXPECT_NEAR(abbe_number(glass), v_d, 1e-9 * v_d);
    for (const double nm : {380.0, 450.0, 550.0, 650.0, 780.0})
      EXPECT_NEAR(glass(nm), n_d + (n_d - 1.0) / v_d * (523655.0 / (nm * nm) - 1.5168), (n_d - 1.0) / v_d * 5e-5)
          << n_d << " " << v_d << " " << nm;
  }
  // SCHOTT's N-BK7 has V_d = 64.17 (catalogue, 2 decimals).
  EXPECT_NEAR(abbe_number(sellmeier_bk7()), 64.17, 0.005);
  // The extension floors the index at 1: a dispersion far beyond any glass's (V_d = 0.2)
  // would take the red end of a 1.2 glass below vacuum's.
  const CauchyIor extreme = CauchyIor::from_abbe_number(1.2, 0.2);
  EXPECT_EQ(extreme(780.0), 1.0);
  EXPECT_GT(extreme(400.0), 1.2);
}

// Least squares in x = 1/λ²: a Cauchy glass's own samples give it back; N-BK7's Sellmeier
// index across 380–780 nm lies within 0.001 of its closest Cauchy glass (the pbrt-v4
// reader's tolerance), and a constant index is a glass without dispersion.
TEST(Dispersion, CauchyFitOfSampledIndices) {
  const CauchyIor cauchy{1.45, 0.0123};
  std::vector<double> nm, n, bk7_n;
  const SellmeierIor bk7 = sellmeier_bk7();
  for (double l = 380.0; l <= 780.0; l += 20.0) {
    nm.push_back(l);
    n.push_back(cauchy(l));
    bk7_n.push_back(bk7(l));
  }
  const CauchyFit exact = fit_cauchy(nm, n);
  EXPECT_NEAR(exact.ior.a, 1.45, 1e-12);
  EXPECT_NEAR(exact.ior.b_um2, 0.0123, 1e-12);
  EXPECT_LT(exact.max_residual, 1e-12);
  const CauchyFit glass = fit_cauchy(nm, bk7_n);
  EXPECT_LT(glass.max_residual, 1e-3);
  EXPECT_GT(glass.max_residual, 0.0);
  EXPECT_NEAR(glass.ior(587.56), bk7(587.56), 1e-3);
  const std::vector<double> one_nm = {550.0, 600.0}, flat = {1.33, 1.33};
  const CauchyFit constant = fit_cauchy(one_nm, flat);
  EXPECT_NEAR(constant.ior.a, 1.33, 1e-12);
  EXPECT_NEAR(constant.ior.b_um2, 0.0, 1e-12);
}

TEST(Conductor, MeasuredIorTables) {
  // At a tabulated point the interpolant returns the CSV row exactly (Au, 582.1 nm).
  const ConductorIor au = conductor_ior("Au");
  EXPECT_DOUBLE_EQ(au.eta(582.1), 0.29);
  EXPECT_DOUBLE_EQ(au.k(582.1), 2.863);
  for (const char* metal : {"Ag", "Cu", "Al"}) {
    const ConductorIor m = conductor_ior(metal);
    for (double nm = 380.0; nm <= 780.0; nm += 50.0) {
      EXPECT_GT(m.eta(nm), 0.0) << metal;
      EXPECT_GT(m.k(nm), 1.0) << metal;  // metals: strongly absorbing across the visible
    }
  }
  EXPECT_THROW(conductor_ior("Unobtainium"), UsageError);
  EXPECT_THROW(conductor_ior("au"), UsageError);
}

}  // namespace
}  // namespace prism::bsdf
