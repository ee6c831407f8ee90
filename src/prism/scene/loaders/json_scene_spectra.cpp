// prism-scene/1: spectra given as data instead of colours (scene/spectral_inputs.h).
//   "spectrum": "F11"                                          a CIE illuminant (emitters)
//   "spectrum": {"blackbody_k": 2700}                          Planck's law (emitters)
//   "spectrum": {"wavelengths_nm": [...], "values": [...]}     measured points
//   "spectrum": {"file": "measured.csv", "column": "red"}      a CSV column (spectrum_csv.h)
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/scene/loaders/json_scene_reader.h"
#include "prism/scene/loaders/spectrum_csv.h"
#include "prism/scene/spectral_inputs.h"
#include "prism/scene/spectrum_table_checks.h"

namespace prism::loaders {
namespace {

color::PiecewiseLinearSpectrum checked_spectrum(std::vector<double> nm, std::vector<double> values, SpectrumUse use,
                                                const std::function<void(std::string_view)>& fail) {
  const std::string problem =
      spectrum_table_problem(nm, values, use == SpectrumUse::reflectance ? 1.0 : kNoSpectrumMaximum);
  if (!problem.empty()) fail(problem);
  return color::PiecewiseLinearSpectrum(std::move(nm), std::move(values));
}

}  // namespace

color::PiecewiseLinearSpectrum JsonSceneReader::read_spectrum(const JsonValue& value, SpectrumUse use) const {
  const auto fail = [&](std::string_view what) { value.fail(what); };
  color::PiecewiseLinearSpectrum spectrum;
  if (value.is_string()) {
    if (use == SpectrumUse::reflectance)
      value.fail("a reflectance spectrum is data: {\"wavelengths_nm\", \"values\"} or {\"file\", \"column\"}");
    const std::string name = value.as_string();
    const auto named = named_emission_spectrum(name);
    if (!named) value.fail(fmt::format("unknown spectrum '{}' (known: {})", name, kEmissionSpectrumNames));
    spectrum = *named;
  } else {
    value.expect_keys({"wavelengths_nm", "values", "blackbody_k", "file", "column"});
    const int forms =
        (value.has("wavelengths_nm") || value.has("values")) + value.has("blackbody_k") + value.has("file");
    if (forms != 1) value.fail("give one of 'wavelengths_nm' with 'values', 'blackbody_k', or 'file'");
    if (value.has("column") && !value.has("file")) value.fail("'column' goes with 'file'");
    if (auto t = value.find("blackbody_k")) {
      if (use == SpectrumUse::reflectance) t->fail("a reflectance cannot be a black body");
      spectrum = blackbody_emission_spectrum(t->as_float(100.0f, 1e6f));
    } else if (auto f = value.find("file")) {
      const std::string column = value.has("column") ? value["column"].as_string() : std::string();
      const std::filesystem::path path = resolve(*f);
      SpectrumColumn data;
      try {
        data = read_spectrum_csv(path, column);
      } catch (const Error& e) {
        f->fail(e.what());
      }
      const auto fail_in_file = [&](std::string_view what) {
        f->fail(fmt::format("{}: {}", path.filename().string(), what));
      };
      spectrum = checked_spectrum(std::move(data.wavelengths_nm), std::move(data.values), use, fail_in_file);
    } else {
      const JsonValue nm_value = value["wavelengths_nm"], values_value = value["values"];
      std::vector<double> nm, values;
      for (const JsonValue& e : nm_value.elements(kMaxSpectrumPoints)) nm.push_back(e.as_double());
      for (const JsonValue& e : values_value.elements(kMaxSpectrumPoints)) values.push_back(e.as_double());
      spectrum = checked_spectrum(std::move(nm), std::move(values), use, fail);
    }
  }
  if (use == SpectrumUse::emission && !(color::spectrum_to_xyz(spectrum).y > 0.0))
    value.fail("the spectrum emits no visible light (it is zero over 380–780 nm)");
  return spectrum;
}

}  // namespace prism::loaders
