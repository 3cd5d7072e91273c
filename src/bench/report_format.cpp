#include "report_format.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace eaci_bench {

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "—";
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0.00"
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << value;
  return s.str();
}

std::string ratio(double ours, double theirs) {
  if (!std::isfinite(ours) || !std::isfinite(theirs) || theirs == 0.0) return "—";
  return fixed(ours / theirs, 2) + "×";
}

MarkdownTable::MarkdownTable(std::vector<std::string> header, std::vector<bool> right_aligned)
    : header_(std::move(header)), right_aligned_(std::move(right_aligned)) {
  right_aligned_.resize(header_.size(), true);
  if (!right_aligned_.empty()) right_aligned_[0] = false;
}

void MarkdownTable::addRow(std::vector<std::string> cells) {
  cells.resize(header_.size());
  rows_.push_back(std::move(cells));
}

std::string MarkdownTable::render() const {
  std::ostringstream s;
  auto line = [&](const std::vector<std::string>& cells) {
    s << "|";
    for (const std::string& cell : cells) s << " " << cell << " |";
    s << "\n";
  };
  line(header_);
  s << "|";
  for (bool right : right_aligned_) s << (right ? "---:|" : "---|");
  s << "\n";
  for (const auto& row : rows_) line(row);
  return s.str();
}

CsvTable::CsvTable(std::vector<std::string> header) : header_(std::move(header)) {}

void CsvTable::addRow(const std::vector<std::string>& cells) { rows_.push_back(cells); }

std::string CsvTable::quote(const std::string& cell) {
  if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
  std::string out = "\"";
  for (char ch : cell) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

std::string CsvTable::render() const {
  std::ostringstream s;
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t k = 0; k < cells.size(); ++k) s << (k ? "," : "") << quote(cells[k]);
    s << "\n";
  };
  line(header_);
  for (const auto& row : rows_) line(row);
  return s.str();
}

std::string csvNumber(double value) {
  if (!std::isfinite(value)) return "";
  std::ostringstream s;
  s << std::setprecision(10) << value;
  return s.str();
}

void makeDirectories(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw std::runtime_error("cannot create directory " + dir + ": " + error.message());
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << text;
  if (!out) throw std::runtime_error("error while writing " + path);
}

void writeJson(const std::string& path, const nlohmann::json& j) { writeText(path, j.dump() + "\n"); }

void writeReport(const std::string& dir, const std::string& name, const ReportFiles& files) {
  makeDirectories(dir);
  const std::string base = dir + "/" + name;
  std::vector<std::string> written = {base + ".json", base + ".csv"};
  writeJson(written[0], files.json);
  writeText(written[1], files.csv);
  for (const auto& [suffix, text] : files.extra) {
    writeText(base + suffix, text);
    written.push_back(base + suffix);
  }
  writeText(base + ".md", files.markdown);
  written.push_back(base + ".md");
  std::cout << "wrote";
  for (std::size_t k = 0; k < written.size(); ++k)
    std::cout << (k == 0 ? " " : k + 1 == written.size() ? " and " : ", ") << written[k];
  std::cout << "\n";
}

}  // namespace eaci_bench
