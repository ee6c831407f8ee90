#pragma once
// Small synthetic scenes with known answers for integrator tests.
#include "prism/render/renderer.h"
#include "prism/scene/scene.h"

namespace prism::test {

// A closed cube whose six inner faces are Lambertian with the given albedo and all emit
// radiance `emitted` towards the inside; the camera sits at the centre. Every ray then
// sees L = Le / (1 - albedo) exactly (the Neumann series of the rendering equation).
Scene make_emitting_enclosure(float albedo, float emitted);

// A 200 × 200 grey Lambertian floor (ρ = 0.5, flat spectrum) in the y = 0 plane, front
// face up, and a camera `eye_height` above its centre looking straight down (image up =
// +z) with the given field of view. No lights: tests add theirs.
Scene make_grey_floor_seen_from_above(float eye_height, float fov_degrees);

// Settings for renders of these floors (make_grey_floor_seen_from_above's, the one below):
// 16² pixels, 64 spp, direct light only (max depth 1), `kind` transport in the default
// working space and upsampling.
RenderSettings floor_from_above_render_settings(TransportKind kind);

// That floor seen from 5 units above with a 30° field of view (every camera ray within 15°
// of the normal), with uvs (u along +x, v along +z), wearing `material` and lit straight
// down by a white directional light of `illuminance_lux`: a Lambertian albedo ρ films as
// ρ · E/π in every pixel, with no noise in RGB transport and only the wavelengths' in
// spectral transport.
Scene make_floor_under_overhead_sun(const Material& material, float illuminance_lux);

// The same floor with per-vertex normals (+y) and uvs (u along +x, or along −x when
// `mirrored_u`; v along +z, i.e. down the image), lit by a delta directional light from
// `toward_light` (illuminance 1 lux), the camera 90 above with a 10° field of view (view
// directions within 5° of the normal; u, v ∈ [0.46, 0.54]): what normal- and bump-map
// tests shade. The material is diffuse, ρ = 0.5; tests add its maps.
Scene make_sunlit_uv_floor(const Vec3f& toward_light, bool mirrored_u = false);

// One triangle in the z = 0 plane, (0,0,0), (1,0,0), (0,1,0), with uvs equal to its x and
// y: what writer round trips of a material need.
TriangleMesh make_uv_triangle();

// The floor of make_grey_floor_seen_from_above(5, 60) with uvs (u along +x, v along +z)
// wearing `material`, lit by a 100 cd point light 2 units above its centre, and the
// settings to render it: RGB, direct light only, size × size pixels, 4 spp. A glossy
// surface shows one highlight at the image centre (image x is world −x).
Scene make_bulb_lit_uv_floor(const Material& material);
RenderSettings direct_light_rgb_settings(int size);

// The mean red of an 8×8 RGB render with direct light only (max depth 1), 2 spp, one
// thread. Under delta lights a Lambertian surface's pixels are then exact: no random
// number reaches a delta light's estimate.
double direct_light_mean_red(const Scene& scene);

}  // namespace prism::test
