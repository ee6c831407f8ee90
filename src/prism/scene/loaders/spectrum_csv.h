#pragma once
// Measured spectra as CSV files: a header row naming the columns, then one row per
// wavelength, the wavelength in nm first (the layout of the CIE tables and of most
// published measurements, e.g. data/cie/*.csv). Blank lines and lines starting with '#'
// are skipped.
#include <filesystem>
#include <string_view>
#include <vector>

namespace prism::loaders {

struct SpectrumColumn {
  std::vector<double> wavelengths_nm;
  std::vector<double> values;
};

// The column named `column` (empty: the first after the wavelength). IoError when the file
// cannot be read; SceneError "file:line: …" for a missing column, a row with the wrong
// number of fields or a field that is not a finite number. Ranges are the caller's to check.
SpectrumColumn read_spectrum_csv(const std::filesystem::path& path, std::string_view column);

}  // namespace prism::loaders
