// SPDX-License-Identifier: Apache-2.0
#include "glider/report/report.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace glider::report {

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

namespace {

// A PNG ends with its IEND chunk (length 0, "IEND", the CRC AE 42 60 82).
bool png_complete(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() < 8) return false;
  in.seekg(-8, std::ios::end);
  char tail[8];
  in.read(tail, sizeof tail);
  return in && std::memcmp(tail, "IEND\xae\x42\x60\x82", sizeof tail) == 0;
}

}  // namespace

void write_file(const std::filesystem::path& path, std::string_view text) {
  const std::filesystem::path temporary = path.string() + ".partial";
  bool ok = false;
  int error = 0;
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();  // flushes: a full disk shows here
    ok = !out.fail();
    error = errno;
  }
  std::error_code rename_error;
  if (ok) std::filesystem::rename(temporary, path, rename_error);
  if (!ok || rename_error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    const std::string why = rename_error ? rename_error.message()
                            : error != 0 ? std::string(std::strerror(error))
                                         : std::string("write failed");
    throw std::runtime_error(path.string() + ": cannot write: " + why);
  }
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
  std::ostringstream out;
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
  write_file(directory_ / name, out.str());
}

void Report::plot(const std::string& name, const std::string& caption, const std::string& script) {
  std::ostringstream out;
  out << "set terminal pngcairo size 900,560 font 'DejaVu Sans,10'\nset output '" << name << ".png'\nset grid\n"
      << script << '\n';
  write_file(directory_ / (name + ".gp"), out.str());
  plots_.push_back(name);
  text_ << "\n![" << caption << "](" << name << ".png)\n\n*" << caption << "*\n";
}

bool Report::finish() {
  write_file(directory_ / "README.md", text_.str());
  bool ok = true;
  for (const auto& name : plots_) {
    const std::string command = "cd '" + directory_.string() + "' && gnuplot '" + name + ".gp'";
    if (std::system(command.c_str()) != 0) {
      std::fprintf(stderr, "glider-validate: gnuplot failed on %s.gp\n", name.c_str());
      ok = false;
    } else if (!png_complete(directory_ / (name + ".png"))) {
      // gnuplot exits 0 when the disk is full, leaving an empty or cut PNG.
      std::error_code ignored;
      std::filesystem::remove(directory_ / (name + ".png"), ignored);
      throw std::runtime_error((directory_ / (name + ".png")).string() +
                               ": cannot write: the plot is empty or cut short (is the disk full?)");
    }
  }
  return ok;
}

}  // namespace glider::report
