#pragma once
// The viewer's "save" actions: the displayed image (PNG or AVIF, with the colour metadata
// of its ODT: sRGB chunk, or cICP + HDR10 mDCv/cLLi for PQ), the film (EXR in the film's
// space) and the camera (JSON snippet, scene/camera_json.h).
#include <filesystem>
#include <string>

#include "prism/viewer/display_worker.h"
#include "prism/viewer/render_session.h"
#include "prism/viewer/viewer_state.h"

namespace prism::viewer {

// Writes the display pipeline's output (`shown.image`), or, for debug views, the 8-bit
// view as shown. Throws UsageError/IoError.
void save_display_image(const std::filesystem::path& path, const DisplayFrame& shown, const DisplayControls& controls);

// Scene-linear means in the film's colour space, with its chromaticities and spp metadata.
void save_film_exr(const std::filesystem::path& path, const FilmFrame& film, const std::string& scene_name);

// Screenshot of the window (RGB8, rows top first) as an 8-bit PNG.
void save_screenshot(const std::filesystem::path& path, const EncodedImage& rgb8);

}  // namespace prism::viewer
