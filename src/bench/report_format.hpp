// Small writers shared by the reports: number formatting, Markdown tables, CSV, files.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace eaci_bench {

// Fixed-point text; "—" for infinity / NaN.
std::string fixed(double value, int decimals);
// "0.85×" style ratio ours / theirs; "—" when either is missing or zero.
std::string ratio(double ours, double theirs);

class MarkdownTable {
 public:
  explicit MarkdownTable(std::vector<std::string> header, std::vector<bool> right_aligned = {});
  void addRow(std::vector<std::string> cells);
  std::string render() const;

 private:
  std::vector<std::string> header_;
  std::vector<bool> right_aligned_;
  std::vector<std::vector<std::string>> rows_;
};

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> header);
  void addRow(const std::vector<std::string>& cells);
  std::string render() const;

 private:
  static std::string quote(const std::string& cell);
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// Plain number for CSV: shortest round-trip text, empty for infinity / NaN.
std::string csvNumber(double value);

// Creates the directory (and its parents). Throws std::runtime_error on failure.
void makeDirectories(const std::string& dir);
void writeText(const std::string& path, const std::string& text);
void writeJson(const std::string& path, const nlohmann::json& j);

// One command's report: DIR/NAME.json, DIR/NAME.csv, DIR/NAME.md and any extra files
// (name suffix and text, e.g. {"_runs.csv", ...}); creates DIR and lists the files on stdout.
struct ReportFiles {
  nlohmann::json json;
  std::string csv;
  std::string markdown;
  std::vector<std::pair<std::string, std::string>> extra;
};
void writeReport(const std::string& dir, const std::string& name, const ReportFiles& files);

}  // namespace eaci_bench
