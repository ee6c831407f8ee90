#include "prism/scene/loaders/spectrum_csv.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/read_to_end.h"

namespace prism::loaders {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    const std::size_t length = comma == std::string_view::npos ? std::string_view::npos : comma - start;
    fields.push_back(trim(line.substr(start, length)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

SpectrumColumn read_spectrum_csv(const std::filesystem::path& path, std::string_view column) {
  const std::string text = read_file_text(path, "spectrum");
  const std::string source = path.filename().string();
  std::vector<std::string_view> header;
  std::size_t column_index = 0;
  SpectrumColumn out;
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = trim(std::string_view(text).substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    const auto fail = [&](std::string_view what) {
      throw SceneError(fmt::format("{}:{}: {}", source, line_number, what));
    };
    std::vector<std::string_view> fields = split_fields(line);
    if (header.empty()) {
      header = std::move(fields);
      if (header.size() < 2) fail("the header needs a wavelength column and at least one value column");
      if (column.empty()) {
        column_index = 1;
      } else {
        for (std::size_t i = 1; i < header.size() && column_index == 0; ++i)
          if (header[i] == column) column_index = i;
        if (column_index == 0) fail(fmt::format("no column named '{}' in the header", column));
      }
      continue;
    }
    if (fields.size() != header.size())
      fail(fmt::format("{} fields where the header has {}", fields.size(), header.size()));
    const auto number = [&](std::string_view field) {
      double v = 0.0;
      const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
      if (ec != std::errc() || ptr != field.data() + field.size() || !std::isfinite(v))
        fail(fmt::format("'{}' is not a finite number", field));
      return v;
    };
    out.wavelengths_nm.push_back(number(fields[0]));
    out.values.push_back(number(fields[column_index]));
  }
  if (header.empty()) throw SceneError(fmt::format("{}: empty file: expected a header row and data rows", source));
  return out;
}

}  // namespace prism::loaders
