#pragma once
// What a tabulated spectrum given as scene data must satisfy, whoever gives it: the JSON
// and pbrt-v4 loaders (which add the file and position) and validate_scene (scenes built in
// code). Piecewise linear between the points, held at the end values outside them
// (color::PiecewiseLinearSpectrum), so:
//   at least 2 points (and at most kMaxSpectrumPoints),
//   wavelengths finite, increasing, within [100, 3000] nm: past the visible range on both
//   sides (UV and IR data often come with it), but nothing that is clearly not nanometres,
//   values finite and ≥ 0, and ≤ 1 for a reflectance (a surface cannot reflect more than it
//   receives).
#include <cstddef>
#include <limits>
#include <span>
#include <string>

namespace prism {

inline constexpr double kMinSpectrumWavelengthNm = 100.0, kMaxSpectrumWavelengthNm = 3000.0;
inline constexpr std::size_t kMaxSpectrumPoints = 100000;
inline constexpr double kNoSpectrumMaximum = std::numeric_limits<double>::infinity();

// The first rule the table breaks, as a message for the caller's error (without the file or
// owner, e.g. "wavelengths must increase: 500 nm follows 510 nm"); empty when it breaks
// none. `max_value` is 1 for reflectances, kNoSpectrumMaximum for emitters.
std::string spectrum_table_problem(std::span<const double> wavelengths_nm, std::span<const double> values,
                                   double max_value);

}  // namespace prism
