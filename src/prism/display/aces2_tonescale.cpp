#include "prism/display/aces2_tonescale.h"

#include <algorithm>
#include <cmath>

namespace prism::display {
namespace {
constexpr double kReference = 100.0;  // n_r: display luminance of relative 1.0
}

Aces2Tonescale::Aces2Tonescale(double peak_luminance_nits) : peak_nits(peak_luminance_nits) {
  const double n = peak_luminance_nits;
  g = 1.15;                        // surround / contrast
  t_1 = 0.04;                      // toe: flare compensation
  const double grey_scene = 0.18;  // c
  const double grey_nits = 10.013; // c_d
  const double grey_gain = 0.14;   // w_g: change of grey per stop of peak
  const double r_hit_min = 128.0, r_hit_max = 896.0;

  const double r_hit = r_hit_min + (r_hit_max - r_hit_min) * (std::log(n / kReference) / std::log(100.0));
  const double m_0 = n / kReference;
  const double m_1 = 0.5 * (m_0 + std::sqrt(m_0 * (m_0 + 4.0 * t_1)));
  const double u = std::pow((r_hit / m_1) / ((r_hit / m_1) + 1.0), g);
  const double m = m_1 / u;
  const double w_i = std::log2(n / 100.0);
  grey_display = grey_nits / kReference * (1.0 + w_i * grey_gain);
  const double g_ip = 0.5 * (grey_display + std::sqrt(grey_display * (grey_display + 4.0 * t_1)));
  const double g_ipp2 = -(m_1 * std::pow(g_ip / m, 1.0 / g)) / (std::pow(g_ip / m, 1.0 / g) - 1.0);
  const double w_2 = grey_scene / g_ipp2;
  s_2 = w_2 * m_1 * kReference;
  const double u_2 = std::pow((r_hit / m_1) / ((r_hit / m_1) + w_2), g);
  m_2 = m_1 / u_2;
  inverse_limit = n / (u_2 * kReference);
  forward_limit = 8.0 * r_hit;
  log_peak = std::log10(n / kReference);
}

double Aces2Tonescale::forward(double scene_y) const {
  const double f = m_2 * std::pow(scene_y / (scene_y + s_2), g);
  return std::max(0.0, f * f / (f + t_1)) * kReference;
}

double Aces2Tonescale::inverse(double display_y) const {
  const double z = std::clamp(display_y / kReference, 0.0, inverse_limit);
  const double f = (z + std::sqrt(z * (4.0 * t_1 + z))) / 2.0;
  return s_2 / (std::pow(m_2 / f, 1.0 / g) - 1.0);
}

}  // namespace prism::display
