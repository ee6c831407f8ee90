#include "prism/scene/loaders/pbrt_params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/spectrum.h"
#include "prism/core/error.h"
#include "prism/scene/spectral_inputs.h"
#include "prism/scene/spectrum_table_checks.h"

namespace prism::loaders {
namespace {

bool is_string_type(std::string_view t) { return t == "string" || t == "texture" || t == "bool"; }

// XYZ (relative) → linear Rec.709.
Vec3f xyz_to_srgb(const Vec3d& xyz) {
  const Vec3d rgb = color::color_space("srgb").xyz_to_rgb * xyz;
  return Vec3f(static_cast<float>(std::max(rgb.x, 0.0)), static_cast<float>(std::max(rgb.y, 0.0)),
               static_cast<float>(std::max(rgb.z, 0.0)));
}

template <typename F>
Vec3f spectrum_color(const F& f, PbrtSpectrumUse use) {
  const Vec3d xyz = color::spectrum_to_xyz(f);
  if (use == PbrtSpectrumUse::illuminant) return xyz.y > 0.0 ? xyz_to_srgb(xyz / xyz.y) : Vec3f(0.0f);
  const double white = color::spectrum_to_xyz([](double) { return 1.0; }).y;
  return xyz_to_srgb(xyz / white);
}

}  // namespace

bool is_pbrt_color_space(std::string_view name) {
  return name == "srgb" || name == "rec2020" || name == "aces2065-1" || name == "dci-p3";
}

PbrtColor pbrt_color_in(const Vec3f& rgb, std::string_view space, bool& clipped) {
  if (space == "srgb") return {rgb, ColorPickerSpace::srgb};
  if (space == "rec2020") return {rgb, ColorPickerSpace::rec2020};
  // pbrt-v4's DCI-P3 has D65 white: Prism's display-p3, which Rec.2020 contains.
  const bool aces = space == "aces2065-1";
  const Mat3 to = aces ? color::conversion_matrix(color::color_space("aces2065-1"), color::color_space("acescg"))
                       : color::conversion_matrix(color::color_space("display-p3"), color::color_space("rec2020"));
  const Vec3d v = to * Vec3d(rgb);
  if (color::is_outside_gamut(v)) clipped = true;
  return {Vec3f(max(v, Vec3d(0.0))), aces ? ColorPickerSpace::acescg : ColorPickerSpace::rec2020};
}

double parse_pbrt_number(const PbrtTokenizer& tokens, const PbrtToken& token) {
  double value = 0.0;
  const char* first = token.text.data();
  const char* last = first + token.text.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || !std::isfinite(value))
    tokens.fail(token.line, fmt::format("expected a number, found '{}'", token.text));
  return value;
}

PbrtParams read_pbrt_params(PbrtTokenizer& tokens, int directive_line) {
  PbrtParams list;
  list.source = tokens.source();
  list.line = directive_line;
  while (tokens.peek().kind == PbrtTokenKind::string) {
    const PbrtToken decl = tokens.next();
    std::istringstream words{std::string(decl.text)};
    PbrtParam p;
    std::string extra;
    if (!(words >> p.type >> p.name) || (words >> extra))
      tokens.fail(decl.line, fmt::format("expected a parameter declaration \"type name\", found \"{}\"", decl.text));
    p.line = decl.line;
    const auto add_value = [&](const PbrtToken& v) {
      if (v.kind == PbrtTokenKind::string) {
        p.strings.emplace_back(v.text);
      } else if (v.kind == PbrtTokenKind::word && (v.text == "true" || v.text == "false")) {
        p.strings.emplace_back(v.text);
      } else if (v.kind == PbrtTokenKind::word) {
        p.numbers.push_back(parse_pbrt_number(tokens, v));
      } else {
        tokens.fail(v.line, fmt::format("expected a value for parameter '{}'", p.name));
      }
    };
    if (tokens.peek().kind == PbrtTokenKind::open_bracket) {
      tokens.next();
      while (tokens.peek().kind != PbrtTokenKind::close_bracket) {
        if (tokens.peek().kind == PbrtTokenKind::end) tokens.fail(decl.line, fmt::format("unterminated '[' for parameter '{}'", p.name));
        add_value(tokens.next());
      }
      tokens.next();
    } else {
      add_value(tokens.next());
    }
    if (!p.numbers.empty() && !p.strings.empty())
      tokens.fail(decl.line, fmt::format("parameter '{}' mixes numbers and strings", p.name));
    if (is_string_type(p.type) && !p.numbers.empty())
      tokens.fail(decl.line, fmt::format("parameter '{}' of type {} needs string values", p.name, p.type));
    list.params.push_back(std::move(p));
  }
  return list;
}

void PbrtParams::fail(const PbrtParam& p, std::string_view message) const {
  throw SceneError(fmt::format("{}:{}: parameter '{}': {}", source, p.line, p.name, message));
}

const PbrtParam* PbrtParams::find(std::string_view name) const {
  for (const auto& p : params)
    if (p.name == name) {
      p.used = true;
      return &p;
    }
  return nullptr;
}

double PbrtParams::get_float(std::string_view name, double fallback) const {
  const PbrtParam* p = find(name);
  if (!p) return fallback;
  if (p->numbers.size() != 1) fail(*p, "expected one number");
  return p->numbers[0];
}

int PbrtParams::get_int(std::string_view name, int fallback) const {
  const double v = get_float(name, fallback);
  if (v != std::floor(v) || std::abs(v) > 2e9) fail(*find(name), "expected an integer");
  return static_cast<int>(v);
}

bool PbrtParams::get_bool(std::string_view name, bool fallback) const {
  const PbrtParam* p = find(name);
  if (!p) return fallback;
  if (p->strings.size() != 1 || (p->strings[0] != "true" && p->strings[0] != "false")) fail(*p, "expected true or false");
  return p->strings[0] == "true";
}

std::string PbrtParams::get_string(std::string_view name, std::string fallback) const {
  const PbrtParam* p = find(name);
  if (!p) return fallback;
  if (p->strings.size() != 1) fail(*p, "expected one string");
  return p->strings[0];
}

std::vector<double> PbrtParams::get_numbers(std::string_view name) const {
  const PbrtParam* p = find(name);
  if (!p) return {};
  if (!p->strings.empty()) fail(*p, "expected numbers");
  return p->numbers;
}

std::optional<Vec3f> PbrtParams::get_point3(std::string_view name) const {
  const PbrtParam* p = find(name);
  if (!p) return std::nullopt;
  if (p->numbers.size() != 3) fail(*p, "expected three numbers");
  return Vec3f(static_cast<float>(p->numbers[0]), static_cast<float>(p->numbers[1]), static_cast<float>(p->numbers[2]));
}

std::optional<Vec3f> PbrtParams::get_color(std::string_view name, PbrtSpectrumUse use,
                                           std::vector<std::string>& approximations) const {
  const PbrtParam* p = find(name);
  if (!p) return std::nullopt;
  const auto where = [&] { return fmt::format("'{}' (line {})", p->name, p->line); };
  if (p->type == "rgb") {
    if (p->numbers.size() != 3) fail(*p, "expected three numbers");
    for (double v : p->numbers)
      if (v < 0.0) fail(*p, "colour components must not be negative");
    return Vec3f(static_cast<float>(p->numbers[0]), static_cast<float>(p->numbers[1]), static_cast<float>(p->numbers[2]));
  }
  if (p->type == "float") {
    if (p->numbers.size() != 1 || p->numbers[0] < 0.0) fail(*p, "expected one non-negative number");
    return Vec3f(static_cast<float>(p->numbers[0]));
  }
  if (p->type == "blackbody") {
    check_blackbody(*p);
    approximations.push_back(fmt::format("{} blackbody {} K as its sRGB colour", where(), p->numbers[0]));
    const color::BlackbodySpectrum bb(p->numbers[0], true);
    return spectrum_color([&](double nm) { return bb(nm); }, use);
  }
  if (p->type == "spectrum") {
    if (!p->strings.empty()) {
      if (p->strings.size() != 1) fail(*p, "expected one spectrum name");
      approximations.push_back(fmt::format("{} named spectrum \"{}\" as a grey", where(), p->strings[0]));
      return use == PbrtSpectrumUse::illuminant ? Vec3f(1.0f) : Vec3f(0.5f);
    }
    const color::PiecewiseLinearSpectrum sampled = sampled_spectrum(*p);
    approximations.push_back(fmt::format("{} sampled spectrum as its sRGB colour", where()));
    return spectrum_color(sampled, use);
  }
  fail(*p, fmt::format("type '{}' is not a colour (rgb, spectrum, blackbody)", p->type));
}

std::optional<PbrtColor> PbrtParams::get_color(std::string_view name, PbrtSpectrumUse use, std::string_view color_space,
                                               std::vector<std::string>& approximations) const {
  const auto rgb = get_color(name, use, approximations);
  if (!rgb) return std::nullopt;
  if (find(name)->type != "rgb") return PbrtColor{*rgb, ColorPickerSpace::srgb};
  bool clipped = false;
  const PbrtColor c = pbrt_color_in(*rgb, color_space, clipped);
  if (clipped)
    approximations.push_back(fmt::format("'{}' (line {}) lies outside ACEScg: clipped to it", name, find(name)->line));
  return c;
}

void PbrtParams::check_blackbody(const PbrtParam& p) const {
  if (p.numbers.size() != 1 || !(p.numbers[0] > 0.0) || p.numbers[0] > 1e6) fail(p, "expected a temperature in kelvin");
}

color::PiecewiseLinearSpectrum PbrtParams::sampled_spectrum(const PbrtParam& p) const {
  const auto& v = p.numbers;
  if (v.size() < 4 || v.size() % 2 != 0) fail(p, "expected (wavelength, value) pairs");
  std::vector<double> nm, values;
  for (std::size_t i = 0; i < v.size(); i += 2) {
    nm.push_back(v[i]);
    values.push_back(v[i + 1]);
  }
  // Reflectances above 1 are not an error here: get_spectrum falls back to the colour.
  const std::string problem = spectrum_table_problem(nm, values, kNoSpectrumMaximum);
  if (!problem.empty()) fail(p, problem);
  return color::PiecewiseLinearSpectrum(std::move(nm), std::move(values));
}

std::optional<color::PiecewiseLinearSpectrum> PbrtParams::get_spectrum(std::string_view name,
                                                                       PbrtSpectrumUse use) const {
  const PbrtParam* p = find(name);
  if (!p) return std::nullopt;
  const bool light = use == PbrtSpectrumUse::illuminant;
  if (p->type == "blackbody" && light) {
    check_blackbody(*p);
    color::PiecewiseLinearSpectrum s = blackbody_emission_spectrum(p->numbers[0]);
    if (!(color::spectrum_to_xyz(s).y > 0.0)) return std::nullopt;  // too cold to be seen: get_color's black
    return s;
  }
  if (p->type != "spectrum") return std::nullopt;
  if (!p->strings.empty()) {
    constexpr std::string_view kPrefix = "stdillum-";
    if (!light || p->strings.size() != 1 || !p->strings[0].starts_with(kPrefix)) return std::nullopt;
    return named_emission_spectrum(std::string_view(p->strings[0]).substr(kPrefix.size()));
  }
  color::PiecewiseLinearSpectrum s = sampled_spectrum(*p);
  if (light ? !(color::spectrum_to_xyz(s).y > 0.0) : *std::max_element(s.values().begin(), s.values().end()) > 1.0)
    return std::nullopt;  // no visible light, or not a reflectance: get_color's colour stands
  return s;
}

std::vector<std::string> PbrtParams::unused() const {
  std::vector<std::string> names;
  for (const auto& p : params)
    if (!p.used) names.push_back(fmt::format("\"{}\" (line {})", p.name, p.line));
  return names;
}

}  // namespace prism::loaders
