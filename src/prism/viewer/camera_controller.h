#pragma once
// Interactive camera motions on prism::Camera (eye/target/up/fov): orbit about the target,
// pan in the image plane, dolly toward the target, and first-person fly/look. Angles in
// radians, distances in scene units; the viewer maps mouse pixels and keys onto these.
#include "prism/scene/scene.h"

namespace prism::viewer {

// Yaw about the camera's up vector and pitch about its right vector, both around the
// target; the pitch stops 1° short of the poles so the view never flips.
Camera orbit(const Camera& camera, double yaw, double pitch);

// Moves eye and target by `right` and `up` along the camera's own axes.
Camera pan(const Camera& camera, double right, double up);

// Moves the eye toward the target by the factor: the distance becomes distance × factor
// (factor < 1 moves closer); never closer than 1e-4 of the original distance.
Camera dolly(const Camera& camera, double factor);

// First-person motion: eye and target move together along forward/right/up.
Camera fly(const Camera& camera, double forward, double right, double up);

// First-person look: the target turns about the eye (yaw, then pitch, clamped like orbit).
Camera look(const Camera& camera, double yaw, double pitch);

// Scene units per image-plane pixel at the target's distance (for panning by pixels).
double pixel_footprint(const Camera& camera, int image_height_px);

// Distance from eye to target.
double view_distance(const Camera& camera);

}  // namespace prism::viewer
