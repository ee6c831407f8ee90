#pragma once
// What a `prism bench` suite produces: named tables of figures (printed as aligned text)
// plus free-form notes, all mirrored in one JSON document for `--json` and the plot script.
#include <deque>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace prism::bench {

// One table: a title, column names and rows of cells. Numbers are kept as numbers in the
// JSON; the text form rounds them to `precision` significant digits.
struct Table {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<nlohmann::json>> rows;

  void add_row(std::vector<nlohmann::json> row) { rows.push_back(std::move(row)); }
};

struct SuiteReport {
  explicit SuiteReport(std::string name) : suite(std::move(name)) {}
  std::string suite;
  std::deque<Table> tables;  // deque: add_table keeps earlier references valid
  std::vector<std::string> notes;
  nlohmann::json data = nlohmann::json::object();  // raw series for plots (per suite)

  Table& add_table(std::string title, std::vector<std::string> columns);
};

// Aligned text tables and notes, as `prism bench` prints them.
std::string format_report(const SuiteReport& report, int precision = 4);

// {"suite", "tables": [{"title", "columns", "rows"}], "notes", "data"}.
nlohmann::json report_json(const SuiteReport& report);

// Machine and build facts for the JSON header: nproc, CPU model, memory, compiler, load.
nlohmann::json machine_json();
// The 1-minute load average (getloadavg), or -1 when unavailable.
double load_average_1min();

}  // namespace prism::bench
