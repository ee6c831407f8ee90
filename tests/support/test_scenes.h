#pragma once
// Small synthetic scenes with known answers for integrator tests.
#include "prism/scene/scene.h"

namespace prism::test {

// A closed cube whose six inner faces are Lambertian with the given albedo and all emit
// radiance `emitted` towards the inside; the camera sits at the centre. Every ray then
// sees L = Le / (1 - albedo) exactly (the Neumann series of the rendering equation).
Scene make_emitting_enclosure(float albedo, float emitted);

}  // namespace prism::test
