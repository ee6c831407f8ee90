#pragma once
// Quantisation of code values to integers with triangular-PDF dither (TPDF, the sum of two
// independent uniforms, ±1 LSB peak): it makes the quantisation error's mean and variance
// independent of the signal, so smooth gradients show no banding (Lipshitz, Wannamaker &
// Vanderkooy 1992, "Quantization and Dither: A Theoretical Survey", JAES 40(5)).
#include <cstdint>

namespace prism::display {

// Deterministic TPDF noise in (−1, 1) LSB for sample `index` under `seed` (a hash, so any
// pixel can be dithered independently and reruns are identical).
double triangular_dither_lsb(std::uint64_t seed, std::uint64_t index);

// round(code · (2^bits − 1) + noise_lsb), clamped to the integer range; NaN → 0.
std::uint16_t quantise_code(double code, int bits, double noise_lsb = 0.0);

}  // namespace prism::display
