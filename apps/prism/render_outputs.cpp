#include "render_outputs.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace prism::cli {
namespace {

bool writable_extension(const std::filesystem::path& name) {
  std::string ext = name.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".exr" || ext == ".hdr" || ext == ".png" || ext == ".avif";
}

}  // namespace

RenderOutputs render_outputs(const Scene& scene, const std::vector<std::string>& given) {
  RenderOutputs out;
  const std::string& own = scene.output_file;
  if (!given.empty()) {
    out.paths.assign(given.begin(), given.end());
    if (!own.empty()) out.note = fmt::format("-o overrides the scene's output file '{}' (Film \"filename\")", own);
    return out;
  }
  const std::filesystem::path defaults[] = {scene.name + ".exr", scene.name + ".png"};
  const std::filesystem::path name(own);
  if (own.empty()) {
    out.paths.assign(std::begin(defaults), std::end(defaults));
  } else if (name.has_parent_path() || name.is_absolute() || !name.has_filename()) {
    out.paths.assign(std::begin(defaults), std::end(defaults));
    out.note = fmt::format("the scene's output file '{}' (Film \"filename\") names a folder, which a scene may not "
                           "choose; writing {} and {} (use -o to choose)",
                           own, defaults[0].string(), defaults[1].string());
  } else if (!writable_extension(name)) {
    out.paths.assign(std::begin(defaults), std::end(defaults));
    out.note = fmt::format("prism does not write the scene's output file '{}' (Film \"filename\"; .exr, .hdr, .png "
                           "or .avif); writing {} and {}",
                           own, defaults[0].string(), defaults[1].string());
  } else {
    out.paths.push_back(name);
  }
  return out;
}

}  // namespace prism::cli
