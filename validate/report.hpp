#pragma once
// What `tendril validate` shows: an aligned table (a row as each run ends),
// the same rows as CSV, and per case a plot of error against wall time.
#include <cstdio>
#include <string>
#include <vector>

#include "case.hpp"
#include "runner.hpp"

namespace tendril::validate {

class Table {
 public:
  // Column widths fit every row the given cases can produce.
  Table(std::FILE* out, const std::vector<const Case*>& cases);
  void header() const;
  void row(const Row& r) const;

 private:
  std::FILE* out_;
  int case_w_ = 4, integrator_w_ = 10, formulation_w_ = 11;
};

std::string percent(double relative);  // "0.0723", "1.2e-05": three significant digits
// The table's note column: default marks, failures, non-convergence.
std::string note(const Row& r);

// Written whole or not at all; throws OutputError if it cannot be (io/atomic_file.hpp).
void write_csv(const std::string& path, const std::vector<Row>& rows);

// Writes DIR/NAME.dat and DIR/NAME.gp (relative paths: rerun with
// `cd DIR && gnuplot NAME.gp`) and runs gnuplot for DIR/NAME.png, log-log
// error against wall time, a series per integrator (and formulation).
// Returns what went wrong, or "".
std::string plot(const Case& c, const std::vector<Row>& rows, const std::string& dir);

}  // namespace tendril::validate
