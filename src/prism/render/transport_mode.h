#pragma once
// Transport modes. The integrator is a template over a Mode: an N-channel "spectrum
// sample" whose channels are N wavelengths (spectral) or the working space's R, G, B.
// Only ColorContext knows what the channels mean; the integrator's code is the same.
#include <string>

#include "prism/color/sampled_spectrum.h"
#include "prism/color/wavelength_sampling.h"

namespace prism {

enum class TransportKind { spectral, rgb };
enum class Upsampling { jakob_hanika, mallett_yuksel };

struct TransportSettings {
  TransportKind kind = TransportKind::spectral;
  int wavelengths = 4;  // spectral: 3, 4 or 8
  // One cosh lobe with evenly rotated partners: the lowest relMSE and the fastest colour
  // convergence of the three on every scene measured (cosh3 has 1.4–4× its relMSE at 3–4
  // wavelengths; BENCHMARKS.md "convergence").
  color::WavelengthStrategy wavelength_strategy = color::WavelengthStrategy::cosh;
  // The seed renderer's nine strata (first sample of a pixel near 600/535/445 nm). Off by
  // default: a pixel whose sample count is not a multiple of nine is biased by up to one
  // stratum's share (decaying as 1/spp), see color/wavelength_sampling.h.
  bool stratify_first_wavelengths = false;
  Upsampling upsampling = Upsampling::jakob_hanika;
  std::string working_space = "srgb";  // rgb: the transport space; spectral: the output space
};

template <int N>
struct SpectralMode {
  static constexpr int kChannels = N;
  static constexpr bool kSpectral = true;
};

struct RgbMode {
  static constexpr int kChannels = 3;
  static constexpr bool kSpectral = false;
};

template <class Mode>
using Spectrum = color::SampledSpectrum<Mode::kChannels>;
template <class Mode>
using Wavelengths = color::SampledWavelengths<Mode::kChannels>;

// Names for messages: "spectral, 4 wavelengths, cosh3" / "rgb (acescg)".
std::string describe(const TransportSettings& settings);

// Throws UsageError for unsupported combinations (wavelength counts, unknown spaces, RGB
// transport in a space without reflectance conversion).
void validate_transport(const TransportSettings& settings);

}  // namespace prism
