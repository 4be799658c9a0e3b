#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/gnuplot.hpp"

namespace tendril::validate {

namespace {

int width_of(const std::string& s) { return static_cast<int>(s.size()); }

// Breaks text at spaces into lines of about equal length, none much over
// `width` characters.
std::string wrap(const std::string& text, std::size_t width) {
  const std::size_t lines = (text.size() + width - 1) / width;
  width = lines > 1 ? text.size() / lines + 12 : width;
  std::string out, line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += (out.empty() ? "" : "\n") + line;
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (char ch : text) {
    if (ch == ' ') flush_word();
    else word += ch;
  }
  flush_word();
  if (!line.empty()) out += (out.empty() ? "" : "\n") + line;
  return out;
}

// Three significant digits without an exponent: 0.00234, 10.2, 171, 1234.
std::string milliseconds(double v) {
  const int decimals = v > 0 ? std::max(0, 2 - static_cast<int>(std::floor(std::log10(v)))) : 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::min(decimals, 6), v);
  return buf;
}

}  // namespace

std::string percent(double relative) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", 100 * relative);
  return buf;
}

std::string note(const Row& r) {
  std::string n;
  if (!r.failure.empty()) n = "failed: " + r.failure;
  else if (!r.outcome.converged) n = "not converged";
  if (r.is_default) {
    const std::string verdict = r.passes() ? "ok" : "FAIL";
    n = "<- default, tol " + percent(r.tolerance) + " %: " + verdict + (n.empty() ? "" : " (" + n + ")");
  }
  return n;
}

Table::Table(std::FILE* out, const std::vector<const Case*>& cases) : out_(out) {
  for (const Case* c : cases) {
    case_w_ = std::max(case_w_, width_of(c->name));
    for (Integrator i : c->integrators) integrator_w_ = std::max(integrator_w_, width_of(integrator_name(i)));
    for (const std::string& f : c->formulations) formulation_w_ = std::max(formulation_w_, width_of(f));
  }
}

void Table::header() const {
  std::fprintf(out_, "%-*s  %-*s  %-*s  %8s  %10s  %9s  %11s  %10s\n", case_w_, "case", integrator_w_, "integrator",
               formulation_w_, "formulation", "segments", "error %", "steps", "force evals", "wall ms");
  const int total = case_w_ + integrator_w_ + formulation_w_ + 8 + 10 + 9 + 11 + 10 + 2 * 7;
  std::fprintf(out_, "%s\n", std::string(total, '-').c_str());
}

void Table::row(const Row& r) const {
  const bool ran = r.failure.empty();
  const std::string remark = note(r);
  std::fprintf(out_, "%-*s  %-*s  %-*s  %8d  %10s  %9llu  %11llu  %10s%s%s\n", case_w_, r.case_name.c_str(),
               integrator_w_, r.integrator.c_str(), formulation_w_, r.formulation.c_str(), r.segments,
               ran ? percent(r.outcome.error).c_str() : "-", static_cast<unsigned long long>(r.outcome.steps),
               static_cast<unsigned long long>(r.outcome.force_evaluations),
               ran ? milliseconds(r.outcome.wall_ms).c_str() : "-", remark.empty() ? "" : "  ", remark.c_str());
  std::fflush(out_);
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ostringstream f;
  f << "case,integrator,formulation,segments,error_percent,steps,force_evaluations,wall_ms,default,"
       "tolerance_percent,converged,failure\n";
  char buf[64];
  for (const Row& r : rows) {
    std::snprintf(buf, sizeof buf, "%.6g", 100 * r.outcome.error);
    const std::string error = buf;
    std::snprintf(buf, sizeof buf, "%.4f", r.outcome.wall_ms);
    f << csv_field(r.case_name) << ',' << csv_field(r.integrator) << ',' << csv_field(r.formulation) << ','
      << r.segments << ',' << (r.failure.empty() ? error : "") << ',' << r.outcome.steps << ','
      << r.outcome.force_evaluations << ',' << buf << ',' << (r.is_default ? 1 : 0) << ',' << percent(r.tolerance)
      << ',' << (r.outcome.converged ? 1 : 0) << ',' << csv_field(r.failure) << '\n';
  }
  write_file_atomically(path, f.str());
}

std::string plot(const Case& c, const std::vector<Row>& rows, const std::string& dir) {
  // Series in table order; failed rows have nothing to plot. An exact zero
  // error has no place on a log axis: it is drawn at a floor (the script says).
  constexpr double kFloorPercent = 1e-12;
  std::vector<std::string> series;
  std::map<std::string, std::vector<const Row*>> points;
  const Row* default_row = nullptr;
  bool floored = false;
  for (const Row& r : rows) {
    if (r.case_name != c.name || !r.failure.empty()) continue;
    const std::string name = c.formulations.size() > 1 ? r.integrator + " " + r.formulation : r.integrator;
    if (!points.count(name)) series.push_back(name);
    points[name].push_back(&r);
    if (r.is_default) default_row = &r;
    floored |= 100 * r.outcome.error < kFloorPercent;
  }
  if (series.empty()) return "no rows to plot for " + c.name;

  auto error_of = [&](const Row& r) { return std::max(100 * r.outcome.error, kFloorPercent); };
  const std::string dat = c.name + ".dat", gp = c.name + ".gp", png = c.name + ".png";
  try {
    std::ostringstream f;
    for (const std::string& name : series) {
      f << "# " << name << "\n# segments wall_ms error_percent\n";
      for (const Row* r : points[name]) f << r->segments << ' ' << r->outcome.wall_ms << ' ' << error_of(*r) << '\n';
      f << "\n\n";
    }
    if (default_row) f << "# default\n" << default_row->segments << ' ' << default_row->outcome.wall_ms << ' '
                       << error_of(*default_row) << "\n\n\n";
    write_file_atomically(dir + "/" + dat, f.str());
  } catch (const OutputError& e) {
    return e.what();
  }
  try {
    std::ostringstream f;
    // One colour per integrator, one dash pattern per formulation.
    static const char* const kColours[] = {"#6a3d9a", "#1b9e77", "#1f78b4", "#d95f02", "#e7298a", "#666666",
                                           "#a6761d", "#e6ab02"};
    auto colour = [&](const Row& r) {
      for (std::size_t i = 0; i < c.integrators.size(); ++i)
        if (r.integrator == integrator_name(c.integrators[i])) return kColours[i % std::size(kColours)];
      return kColours[0];
    };
    auto dashes = [&](const Row& r) {
      for (std::size_t i = 0; i < c.formulations.size(); ++i)
        if (r.formulation == c.formulations[i]) return i + 1;
      return std::size_t{1};
    };
    f << "# Written by `tendril validate --plots`: error against wall time for case " << c.name << ".\n"
      << "set terminal pngcairo size 960,640 font 'sans,11'\n"
      // `out` lets tendril validate render to a temporary file and rename it.
      << "if (!exists('out')) out = " << gnuplot_quote(png) << "\nset output out\n"
      << "set title " << gnuplot_quote(c.name + "\n" + wrap(c.reference, 100)) << " noenhanced font 'sans,10'\n"
      << "set logscale xy\nset format y '%g'\nset format x '%g'\n"
      << "set autoscale fix\nset offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06\n"
      << "set xlabel 'wall time of the relaxation [ms]'\n"
      << "set ylabel 'error against the reference [%]'\n"
      << "set grid xtics ytics lc rgb '#dddddd'\n"
      << "set key outside right top noenhanced\n"
      << "set label 1 " << gnuplot_quote("point labels: " + c.resolution) << " at screen 0.98, screen 0.08 right font 'sans,9'\n"
      << "plot \\\n";
    for (std::size_t i = 0; i < series.size(); ++i) {
      const Row& first = *points[series[i]].front();
      f << "  " << gnuplot_quote(dat) << " index " << i << " using 2:3 with linespoints lw 2 dt " << dashes(first)
        << " pt " << 5 + 2 * (i % 6) << " ps 1.1 lc rgb '" << colour(first) << "' title " << gnuplot_quote(series[i])
        << ", \\\n";
    }
    // The segment counts once, beside the first series.
    f << "  " << gnuplot_quote(dat) << " index 0 using 2:3:(sprintf('%d', $1)) with labels offset char 0,1 "
      << "font 'sans,9' notitle";
    if (default_row)
      f << ", \\\n  " << gnuplot_quote(dat) << " index " << series.size()
        << " using 2:3 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'default'";
    // A function: the autoscaled range keeps the tolerance in view.
    f << ", \\\n  " << 100 * c.tolerance << " with lines dt 2 lw 1.5 lc rgb '#aa0000' title "
      << gnuplot_quote("tolerance " + percent(c.tolerance) + " %") << "\n";
    if (floored) f << "# errors of exactly 0 are drawn at " << kFloorPercent << " %\n";
    write_file_atomically(dir + "/" + gp, f.str());
  } catch (const OutputError& e) {
    return e.what();
  }
  // gnuplot draws into a temporary name; the picture replaces the old one
  // only when it is complete.
  const std::string temp_png = "." + png + ".tmp";
  if (const std::string failed = run_gnuplot(dir, gp, "out='" + temp_png + "'", c.name + ".gnuplot.log");
      !failed.empty()) {
    std::remove((dir + "/" + temp_png).c_str());
    return failed;
  }
  if (std::rename((dir + "/" + temp_png).c_str(), (dir + "/" + png).c_str()) != 0) {
    std::remove((dir + "/" + temp_png).c_str());
    return "cannot move " + dir + "/" + temp_png + " to " + png;
  }
  return "";
}

}  // namespace tendril::validate
