#pragma once
// Switches read from the environment for comparisons (PRISM_SAMPLER_SCALAR,
// PRISM_SHADE_SCALAR, …): set means present, non-empty and not "0".
#include <cstdlib>

namespace prism {

inline bool env_flag(const char* name) {
  const char* value = std::getenv(name);
  return value && *value && *value != '0';
}

}  // namespace prism
