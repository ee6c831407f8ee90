#pragma once
// The files `prism render` writes when no -o is given: the file the scene names for itself
// (pbrt-v4's Film "filename"), else SCENE.exr and SCENE.png, all in the current folder.
#include <filesystem>
#include <string>
#include <vector>

#include "prism/scene/scene.h"

namespace prism::cli {

struct RenderOutputs {
  std::vector<std::filesystem::path> paths;
  std::string note;  // one line for stderr when the scene's own output name is not used, and why
};

// `given`: the -o names (their order kept). The scene's name is used as pbrt-v4 uses it,
// relative to the current folder, when it is a plain file name with an extension Prism
// writes (.exr, .hdr, .png, .avif); a name with a folder is not (a scene file chooses no
// place to write to), nor one Prism cannot write: the note says what is written instead.
RenderOutputs render_outputs(const Scene& scene, const std::vector<std::string>& given);

}  // namespace prism::cli
