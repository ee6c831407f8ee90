#include "prism/render/transport_mode.h"

#include <fmt/format.h>

#include "prism/color/color_space.h"
#include "prism/core/error.h"

namespace prism {

std::string describe(const TransportSettings& s) {
  if (s.kind == TransportKind::rgb) return fmt::format("rgb ({})", color::color_space(s.working_space).name);
  return fmt::format("spectral, {} wavelengths, {}{}", s.wavelengths, color::wavelength_strategy_name(s.wavelength_strategy),
                     s.upsampling == Upsampling::jakob_hanika ? ", jakob-hanika" : ", mallett-yuksel");
}

void validate_transport(const TransportSettings& s) {
  if (s.kind == TransportKind::spectral && s.wavelengths != 3 && s.wavelengths != 4 && s.wavelengths != 8)
    throw UsageError(fmt::format("--wavelengths must be 3, 4 or 8 (got {})", s.wavelengths));
  const std::string& name = color::color_space(s.working_space).name;  // throws for unknown names
  if (name != "srgb" && name != "acescg" && name != "rec2020")
    throw UsageError(fmt::format("--working-space must be srgb, acescg or rec2020 (got {})", s.working_space));
}

}  // namespace prism
