// SPDX-License-Identifier: Apache-2.0
#include "glider/report/report.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace glider::report {

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

Report::Report(std::filesystem::path directory) : directory_(std::move(directory)) {
  std::filesystem::create_directories(directory_);
}

void Report::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  text_ << "\n|";
  for (const auto& h : header) text_ << ' ' << h << " |";
  text_ << "\n|";
  for (std::size_t i = 0; i < header.size(); ++i) text_ << "---|";
  text_ << '\n';
  for (const auto& row : rows) {
    text_ << '|';
    for (const auto& cell : row) text_ << ' ' << cell << " |";
    text_ << '\n';
  }
  text_ << '\n';
}

void Report::data(const std::string& name, const std::vector<std::string>& column_names,
                  const std::vector<std::vector<double>>& columns) {
  std::ofstream out(directory_ / name);
  out << '#';
  for (const auto& c : column_names) out << ' ' << c;
  out << '\n';
  const std::size_t rows = columns.empty() ? 0 : columns.front().size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double v = columns[c][r];
      out << (c ? " " : "");
      if (std::isfinite(v)) {
        out << v;
      } else {
        out << "NaN";
      }
    }
    out << '\n';
  }
}

void Report::plot(const std::string& name, const std::string& caption, const std::string& script) {
  std::ofstream out(directory_ / (name + ".gp"));
  out << "set terminal pngcairo size 900,560 font 'DejaVu Sans,10'\nset output '" << name << ".png'\nset grid\n"
      << script << '\n';
  plots_.push_back(name);
  text_ << "\n![" << caption << "](" << name << ".png)\n\n*" << caption << "*\n";
}

bool Report::finish() {
  {
    std::ofstream out(directory_ / "README.md");
    out << text_.str();
  }
  bool ok = true;
  for (const auto& name : plots_) {
    const std::string command = "cd '" + directory_.string() + "' && gnuplot '" + name + ".gp'";
    if (std::system(command.c_str()) != 0) {
      std::fprintf(stderr, "glider-validate: gnuplot failed on %s.gp\n", name.c_str());
      ok = false;
    }
  }
  return ok;
}

}  // namespace glider::report
