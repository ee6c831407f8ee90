#pragma once
// The rendering transforms (`--rendering`): how scene-linear light becomes display light,
// each combined with a display target (`--odt`, aces_output_transform.h's OdtId names the
// targets). One name↔enum table for the CLI, the viewer and file metadata.
//
//   aces1        ACES 1.x RRT + ODT (aces_output_transform.h), every target
//   aces2        ACES 2.0 Output Transforms (aces2_output_transform.h), every target but `none`
//   agx          Troy Sobotka's AgX (agx.h), SDR targets
//   pbr-neutral  Khronos PBR Neutral (pbr_neutral.h), SDR targets
#include <string>
#include <string_view>
#include <vector>

#include "prism/display/aces_output_transform.h"
#include "prism/display/display_encoding.h"

namespace prism::display {

enum class Rendering { aces1, aces2, agx, pbr_neutral };

// What `render`, `tonemap` and `view` use without --rendering (docs/display-pipeline.md
// says why).
inline constexpr Rendering kDefaultRendering = Rendering::aces1;

// Case-insensitive; '_' accepted for '-'. Unknown: UsageError listing the names.
Rendering parse_rendering(std::string_view name);
std::string_view rendering_name(Rendering r);
std::vector<std::string> rendering_names();

// Whether the rendering defines an output for the target: aces1 every target (and `none`);
// agx and pbr-neutral the 100-nit SDR targets only (both are SDR display renderings).
bool rendering_supports_target(Rendering r, OdtId target);
// UsageError "--rendering X has no output for --odt Y (valid: …)" when it does not.
void require_rendering_target(Rendering r, OdtId target);
// The targets a rendering supports, by name, in OdtId order.
std::vector<std::string> rendering_target_names(Rendering r);

// The encoding of the target under the rendering when none is asked for: the ODT's own for
// aces1; the AgX configuration's display EOTFs for agx (2.2 power for sRGB and Display P3,
// BT.1886 for Rec.709 and Rec.2020); the target's for pbr-neutral; for aces2 the Academy
// preset's (the target's, but γ 2.6 for P3-D65 SDR).
DisplayEncoding default_encoding(Rendering r, OdtId target);

// The ACES 2.0 preset a target maps to (the Academy's, per tests/data/oracles/
// aces2_targets.csv): its peak and limiting primaries (prism::color names). rec2020-100nit has
// no Academy preset: SDR 100 nits limited to Rec.709, in a Rec.2020 container.
struct Aces2Preset {
  double peak_nits;
  std::string_view limiting_primaries;
};
Aces2Preset aces2_preset(OdtId target);

}  // namespace prism::display
