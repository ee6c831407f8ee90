#pragma once
// Parameter lists of pbrt-v4 directives: `"type name" value` or `"type name" [values]`.
// Lookups mark a parameter used, so the loader can warn about every parameter it ignored.
#include <optional>
#include <string>
#include <vector>

#include "prism/color/spectrum.h"
#include "prism/core/vec.h"
#include "prism/scene/material.h"
#include "prism/scene/loaders/pbrt_tokenizer.h"

namespace prism::loaders {

struct PbrtParam {
  std::string type, name;
  std::vector<double> numbers;
  std::vector<std::string> strings;  // string, texture, bool ("true"/"false") and named spectra
  int line = 0;
  mutable bool used = false;
};

// A colour and the primaries it is given with.
struct PbrtColor {
  Vec3f rgb{1.0f};
  ColorPickerSpace space = ColorPickerSpace::srgb;
};

// pbrt-v4's colour spaces, which its ColorSpace directive names: srgb, rec2020, aces2065-1
// and dci-p3 (whose white is D65 in pbrt-v4, as in Display P3).
bool is_pbrt_color_space(std::string_view name);
// An rgb given in the pbrt colour space `space` as Prism holds it: srgb and rec2020 as they
// are; aces2065-1 in ACEScg and dci-p3 in Rec.2020, exactly (conversions between spaces of
// one white). Components that fall below 0 (AP0 colours outside AP1) are clipped and
// `clipped` set.
PbrtColor pbrt_color_in(const Vec3f& rgb, std::string_view space, bool& clipped);

// How a spectrum is approximated by an RGB colour: reflectances under equal energy
// (white = 1), illuminants normalised to luminance 1 as pbrt-v4 normalises light spectra.
enum class PbrtSpectrumUse { reflectance, illuminant };

class PbrtParams {
 public:
  std::vector<PbrtParam> params;
  std::string source;  // file name, for messages
  int line = 0;        // the directive's line

  const PbrtParam* find(std::string_view name) const;
  bool has(std::string_view name) const { return find(name) != nullptr; }
  double get_float(std::string_view name, double fallback) const;
  int get_int(std::string_view name, int fallback) const;
  bool get_bool(std::string_view name, bool fallback) const;
  std::string get_string(std::string_view name, std::string fallback) const;
  std::vector<double> get_numbers(std::string_view name) const;  // empty when absent
  std::optional<Vec3f> get_point3(std::string_view name) const;
  // rgb / spectrum / blackbody / float parameters as a linear Rec.709 colour. Spectra are
  // approximated; each approximation is described in `approximations`.
  std::optional<Vec3f> get_color(std::string_view name, PbrtSpectrumUse use,
                                 std::vector<std::string>& approximations) const;
  // The same with its primaries: an "rgb" parameter is in `color_space` (the pbrt colour
  // space in effect, pbrt_color_in); spectra and floats approximated in Rec.709.
  std::optional<PbrtColor> get_color(std::string_view name, PbrtSpectrumUse use, std::string_view color_space,
                                     std::vector<std::string>& approximations) const;
  // The parameter as a spectrum Prism renders as data (scene/spectral_inputs.h), where it is
  // one: for lights a `blackbody`, a CIE illuminant by pbrt-v4's name ("stdillum-D65", -D50,
  // -A, -F1 … -F12) or sampled (λ, value) pairs; for reflectances sampled pairs within
  // [0, 1]. Nothing otherwise (rgb, float, other named spectra): get_color approximates those.
  // Malformed values fail as in get_color.
  std::optional<color::PiecewiseLinearSpectrum> get_spectrum(std::string_view name, PbrtSpectrumUse use) const;
  // Names of parameters no lookup asked for, with their lines ("name (line 4)").
  std::vector<std::string> unused() const;

  [[noreturn]] void fail(const PbrtParam& p, std::string_view message) const;

 private:
  void check_blackbody(const PbrtParam& p) const;
  // (λ, value) pairs, checked (an even count ≥ 4, λ increasing, values ≥ 0): fails at `p` otherwise.
  color::PiecewiseLinearSpectrum sampled_spectrum(const PbrtParam& p) const;
};

// Reads parameters until the next token is not a quoted string.
PbrtParams read_pbrt_params(PbrtTokenizer& tokens, int directive_line);

// Parses a bare word as a number; throws SceneError at `line` otherwise.
double parse_pbrt_number(const PbrtTokenizer& tokens, const PbrtToken& token);

}  // namespace prism::loaders
