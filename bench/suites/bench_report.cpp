#include "bench_report.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "prism/core/version.h"

namespace prism::bench {
namespace {

std::string cell_text(const nlohmann::json& v, int precision) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (v.is_number_float()) return fmt::format("{:.{}g}", v.get<double>(), precision);
  if (v.is_null()) return "-";
  return v.dump();
}

// First line of /proc/cpuinfo (or /proc/meminfo) that starts with `key`, after the colon.
std::string proc_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    return value;
  }
  return "unknown";
}

}  // namespace

Table& SuiteReport::add_table(std::string title, std::vector<std::string> columns) {
  tables.push_back(Table{std::move(title), std::move(columns), {}});
  return tables.back();
}

std::string format_report(const SuiteReport& report, int precision) {
  std::ostringstream out;
  for (const Table& t : report.tables) {
    std::vector<std::vector<std::string>> cells;
    std::vector<std::size_t> width(t.columns.size(), 0);
    cells.push_back(t.columns);
    for (const auto& row : t.rows) {
      std::vector<std::string> r;
      for (const auto& v : row) r.push_back(cell_text(v, precision));
      cells.push_back(std::move(r));
    }
    for (const auto& r : cells)
      for (std::size_t c = 0; c < r.size() && c < width.size(); ++c) width[c] = std::max(width[c], r[c].size());
    out << "## " << report.suite << ": " << t.title << '\n';
    for (std::size_t i = 0; i < cells.size(); ++i) {
      for (std::size_t c = 0; c < cells[i].size() && c < width.size(); ++c)
        out << (c ? "  " : "") << (c ? fmt::format("{:>{}}", cells[i][c], width[c])
                                     : fmt::format("{:<{}}", cells[i][c], width[c]));
      out << '\n';
      if (i == 0) {
        for (std::size_t c = 0; c < width.size(); ++c) out << (c ? "  " : "") << std::string(width[c], '-');
        out << '\n';
      }
    }
    out << '\n';
  }
  for (const auto& n : report.notes) out << "note: " << n << '\n';
  return out.str();
}

nlohmann::json report_json(const SuiteReport& report) {
  nlohmann::json tables = nlohmann::json::array();
  for (const Table& t : report.tables) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : t.rows) rows.push_back(r);
    tables.push_back({{"title", t.title}, {"columns", t.columns}, {"rows", rows}});
  }
  return {{"suite", report.suite}, {"tables", tables}, {"notes", report.notes}, {"data", report.data}};
}

double load_average_1min() {
  double load[1];
  return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

nlohmann::json machine_json() {
  const std::string mem_kb = proc_field("/proc/meminfo", "MemTotal");
#if defined(__clang__)
  const std::string compiler = fmt::format("clang {}.{}.{}", __clang_major__, __clang_minor__, __clang_patchlevel__);
#elif defined(__GNUC__)
  const std::string compiler = fmt::format("gcc {}.{}.{}", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#else
  const std::string compiler = "unknown";
#endif
  return {{"hardware_threads", std::thread::hardware_concurrency()},
          {"cpu_model", proc_field("/proc/cpuinfo", "model name")},
          {"memory", mem_kb},
          {"compiler", compiler},
          {"prism_version", kVersion},
          {"build_type", kBuildType},
          {"load_average_1min", load_average_1min()}};
}

}  // namespace prism::bench
