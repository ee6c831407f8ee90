// `prism color spectrum` and `prism color wavelengths`: thin adapters over the spectral
// half of prism::color (upsampling, emission, wavelength sampling). Output is plain
// numbers printed with %.9g, one record per line.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "cmd_color.h"
#include "prism/color/color_space.h"
#include "prism/color/emission_spectrum.h"
#include "prism/color/jakob_hanika_table.h"
#include "prism/color/mallett_yuksel.h"
#include "prism/color/wavelength_sampling.h"
#include "prism/core/error.h"
#include "prism/core/pcg32.h"

namespace prism::cli {
namespace {

namespace color = prism::color;


template <typename Integer>
Integer parse_integer(const std::string& text, const std::string& what, Integer min_value, Integer max_value) {
  Integer value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < min_value || value > max_value)
    throw UsageError("malformed or out-of-range integer '" + text + "' for " + what + " (expected " +
                     std::to_string(min_value) + ".." + std::to_string(max_value) + ")");
  return value;
}

void print_spectrum(const std::function<double(double)>& s) {
  for (int nm = static_cast<int>(color::kVisibleMinNm); nm <= static_cast<int>(color::kVisibleMaxNm); ++nm)
    std::printf("%d %.9g\n", nm, s(nm));
}

void add_spectrum(CLI::App& parent, Action& action) {
  struct Options {
    std::string space = "srgb", method = "jakob-hanika", nits = "100";
    std::vector<std::string> rgb;
    bool emission = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = parent.add_subcommand("spectrum", "Upsample a linear RGB colour to a spectrum");
  cmd->add_option("rgb", opt->rgb, "Linear R G B in the chosen space")->expected(3)->required();
  cmd->add_option("--space", opt->space, "Colour space of R G B: srgb|acescg|rec2020 (and aliases)")
      ->capture_default_str()
      ->type_name("SPACE");
  cmd->add_option("--method", opt->method,
                  "jakob-hanika (sigmoid polynomial, Jakob & Hanika 2019) or mallett-yuksel "
                  "(sRGB basis, Mallett & Yuksel 2019; srgb only)")
      ->capture_default_str()
      ->type_name("METHOD");
  cmd->add_flag("--emission", opt->emission,
                "Emission rule: adapt to illuminant E (Bradford), fit, scale so 683*int(S*ybar) = --nits; "
                "values are spectral radiance in W/(m^2 sr nm). Without it: the reflectance in [0,1] a "
                "spectral render uses (components clamped to [0,1]), which under a flat (illuminant E) "
                "light, adapted to the space's white, has the colour R G B");
  cmd->add_option("--nits", opt->nits, "Luminance of the emission spectrum in cd/m^2")
      ->capture_default_str()
      ->type_name("L");
  cmd->footer("Output: one line per wavelength, 380..780 nm in 1 nm steps: `lambda_nm value` (%.9g).");
  cmd->callback([opt, &action] {
    action = [opt] {
      const Vec3d rgb{parse_number(opt->rgb[0], "R"), parse_number(opt->rgb[1], "G"),
                      parse_number(opt->rgb[2], "B")};
      const color::ColorSpace& space = color::color_space(opt->space);
      if (opt->method == "mallett-yuksel") {
        if (space.name != "srgb") throw UsageError("mallett-yuksel needs --space srgb (its basis is for sRGB under D65)");
        if (opt->emission) throw UsageError("mallett-yuksel describes reflectances; use --method jakob-hanika with --emission");
        const color::MallettYukselSpectrum s(color::mallett_yuksel_weights_under_e(rgb));
        print_spectrum([&](double nm) { return s(nm); });
      } else if (opt->method == "jakob-hanika") {
        if (opt->emission) {
          const double nits = parse_number(opt->nits, "--nits");
          if (nits < 0.0) throw UsageError("--nits must not be negative");
          const color::EmissionSpectrum s = color::emission_spectrum(rgb, space, nits);
          print_spectrum([&](double nm) { return s(nm); });
        } else {
          const color::SigmoidPolynomial s = color::JakobHanikaTable::get(space.name).lookup(rgb);
          print_spectrum([&](double nm) { return s(nm); });
        }
      } else {
        throw UsageError("unknown method '" + opt->method + "' (known: jakob-hanika, mallett-yuksel)");
      }
      return 0;
    };
  });
}

void add_wavelengths(CLI::App& parent, Action& action) {
  struct Options {
    std::string strategy = "hero", n = "4", count = "1", seed = "0";
    bool stratified = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = parent.add_subcommand("wavelengths", "Draw wavelength samples with a sampling strategy");
  cmd->add_option("--strategy", opt->strategy,
                  "hero (Wilkie 2014: uniform + rotated partners), cosh (Radziszewski 2009), "
                  "cosh3 (three cosh lobes, one per slot, balance-heuristic pdf)")
      ->capture_default_str()
      ->type_name("NAME");
  cmd->add_option("--n", opt->n, "Wavelengths per sample, 1..64")->capture_default_str()->type_name("N");
  cmd->add_option("--count", opt->count, "Number of samples (lines)")->capture_default_str()->type_name("K");
  cmd->add_option("--seed", opt->seed, "PCG32 seed")->capture_default_str()->type_name("S");
  cmd->add_flag("--stratified", opt->stratified,
                "Stratify the primary number over nine strata, middle stratum first (line i uses stratum i mod 9)");
  cmd->footer(
      "Output: K lines, each `l_1 .. l_N p_1 .. p_N` (%.9g): N wavelengths in nm, then the pdf (1/nm) each is "
      "accounted with in the estimator (1/N) sum f(l_i)/p_i. For cosh3 p_i is the average of the lobe pdfs.");
  cmd->callback([opt, &action] {
    action = [opt] {
      const color::WavelengthStrategy strategy = color::parse_wavelength_strategy(opt->strategy);
      const int n = parse_integer<int>(opt->n, "--n", 1, 64);
      const long count = parse_integer<long>(opt->count, "--count", 0, 100000000L);
      const auto seed = parse_integer<std::uint64_t>(opt->seed, "--seed", 0, UINT64_MAX);
      Pcg32 rng(seed, 0x5eedu);
      std::vector<double> nm(static_cast<std::size_t>(n)), pdf(static_cast<std::size_t>(n));
      for (long line = 0; line < count; ++line) {
        double u = rng.next_double();
        if (opt->stratified) u = color::stratified_wavelength_u(static_cast<std::uint64_t>(line), u);
        for (int i = 0; i < n; ++i) {
          nm[static_cast<std::size_t>(i)] = color::sample_wavelength_slot(strategy, i, color::slot_u(strategy, u, i, n));
          pdf[static_cast<std::size_t>(i)] = color::wavelength_pdf(strategy, n, nm[static_cast<std::size_t>(i)]);
        }
        for (int i = 0; i < 2 * n; ++i)
          std::printf(i == 0 ? "%.9g" : " %.9g", i < n ? nm[static_cast<std::size_t>(i)] : pdf[static_cast<std::size_t>(i - n)]);
        std::printf("\n");
      }
      return 0;
    };
  });
}

}  // namespace

void add_color_spectrum_commands(CLI::App& color, Action& action) {
  add_spectrum(color, action);
  add_wavelengths(color, action);
}

}  // namespace prism::cli
