#include "prism/display/rendering.h"

#include <array>
#include <cctype>
#include <string>

#include "prism/core/enum_names.h"
#include "prism/core/error.h"

namespace prism::display {
namespace {

constexpr std::array<EnumName<Rendering>, 4> kRenderings{{
    {Rendering::aces1, "aces1"},
    {Rendering::aces2, "aces2"},
    {Rendering::agx, "agx"},
    {Rendering::pbr_neutral, "pbr-neutral"},
}};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

Rendering parse_rendering(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (const std::optional<Rendering> r = enum_value(kRenderings, n)) return *r;
  throw UsageError("unknown rendering '" + std::string(name) + "' (valid: " + enum_name_list(kRenderings) + ")");
}

std::string_view rendering_name(Rendering r) { return enum_name(kRenderings, r); }

std::vector<std::string> rendering_names() { return enum_names(kRenderings); }

bool rendering_supports_target(Rendering r, OdtId target) {
  if (r == Rendering::aces1) return true;
  if (r == Rendering::aces2) return target != OdtId::none;
  const OdtDescription& odt = odt_description(target);
  return target != OdtId::none && !odt.hdr;
}

std::vector<std::string> rendering_target_names(Rendering r) {
  std::vector<std::string> names;
  for (const std::string& name : odt_names())
    if (rendering_supports_target(r, parse_odt(name))) names.push_back(name);
  return names;
}

void require_rendering_target(Rendering r, OdtId target) {
  if (rendering_supports_target(r, target)) return;
  throw UsageError("--rendering " + std::string(rendering_name(r)) + " has no output for --odt " +
                   std::string(odt_description(target).name) + " (valid: " + joined(rendering_target_names(r)) + ")");
}

DisplayEncoding default_encoding(Rendering r, OdtId target) {
  const DisplayEncoding odt_encoding = odt_description(target).default_encoding;
  if (r == Rendering::agx && odt_encoding == DisplayEncoding::srgb) return DisplayEncoding::gamma22;
  // ACES 2.0's SDR P3-D65 preset encodes with γ 2.6 (OCIO's "G2.6-P3-D65" display).
  if (r == Rendering::aces2 && target == OdtId::p3d65_100nit) return DisplayEncoding::gamma26;
  return odt_encoding;
}

Aces2Preset aces2_preset(OdtId target) {
  const OdtDescription& odt = odt_description(target);
  switch (target) {
    case OdtId::srgb_100nit:
    case OdtId::rec709_100nit:
    case OdtId::rec2020_100nit: return {100.0, "srgb"};
    case OdtId::p3d65_100nit: return {100.0, "display-p3"};
    case OdtId::rec2020_pq_1000nit:
    case OdtId::rec2020_pq_2000nit:
    case OdtId::rec2020_pq_4000nit: return {odt.white_nits, "rec2020"};
    case OdtId::p3d65_pq_1000nit: return {odt.white_nits, "display-p3"};
    case OdtId::none: break;
  }
  throw UsageError("--rendering aces2 has no output for --odt none");
}

}  // namespace prism::display
