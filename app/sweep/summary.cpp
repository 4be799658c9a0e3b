#include "sweep/summary.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/gnuplot.hpp"

namespace tendril::sweep {

namespace {

namespace fs = std::filesystem;

std::optional<double> number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

std::string figure_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string md(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

// A file name part: letters, digits, '-' and '_' kept, the rest '_'.
std::string file_part(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return out;
}

// The values a parameter takes, in plan order, each once.
std::vector<std::string> levels(const Plan& plan, std::size_t param) {
  std::vector<std::string> out;
  for (const PlannedRun& r : plan.runs)
    if (std::find(out.begin(), out.end(), r.values[param]) == out.end()) out.push_back(r.values[param]);
  return out;
}

const std::string* figure_of(const RunState& s, const std::string& figure) {
  if (s.outcome.kind != Outcome::kOk) return nullptr;
  auto it = s.figures.find(figure);
  return it == s.figures.end() || it->second.empty() ? nullptr : &it->second;
}

std::string plan_line(const Plan& plan) {
  std::int64_t first = plan.runs.front().seed, last = first;
  for (const PlannedRun& r : plan.runs) first = std::min(first, r.seed), last = std::max(last, r.seed);
  std::string line = std::to_string(plan.runs.size()) + " runs of `" + plan.scene + "`: ";
  for (std::size_t p = 0; p < plan.params.size(); ++p) {
    line += (p ? "; " : "") + plan.params[p] + " = ";
    const auto values = levels(plan, p);
    for (std::size_t k = 0; k < values.size(); ++k) line += (k ? ", " : "") + values[k];
  }
  line += std::string(plan.params.empty() ? "" : "; ") + "seeds " + std::to_string(first) +
          (last != first ? ".." + std::to_string(last) : "");
  if (plan.steps >= 0) line += "; --steps " + std::to_string(plan.steps);
  return line + ".";
}

// The plots of one figure against each parameter: points for every run, a
// line through the means per value. Returns the gnuplot commands; the data
// go into `data` as inline blocks.
std::string figure_plots(const Plan& plan, const Gathered& g, const std::string& figure, std::string& data,
                         std::vector<std::string>& pngs) {
  std::string gp;
  for (std::size_t p = 0; p < plan.params.size(); ++p) {
    const auto values = levels(plan, p);
    bool numeric = true;
    for (const std::string& v : values) numeric &= number(v).has_value();
    const std::string block = "$" + file_part(figure) + "_" + std::to_string(p);
    std::map<std::string, std::pair<double, int>> sums;
    data += block + " << EOD\n";
    for (std::size_t k = 0; k < plan.runs.size(); ++k) {
      const std::string* text = figure_of(g.runs()[k], figure);
      const auto y = text ? number(*text) : std::nullopt;
      if (!y || !std::isfinite(*y)) continue;
      const std::string& v = plan.runs[k].values[p];
      const std::size_t level = std::size_t(std::find(values.begin(), values.end(), v) - values.begin());
      data += (numeric ? v : std::to_string(level)) + " " + figure_text(*y) + "\n";
      sums[v].first += *y;
      ++sums[v].second;
    }
    data += "EOD\n" + block + "_mean << EOD\n";
    for (std::size_t level = 0; level < values.size(); ++level)
      if (sums.count(values[level]))
        data += (numeric ? values[level] : std::to_string(level)) + " " +
                figure_text(sums[values[level]].first / sums[values[level]].second) + "\n";
    data += "EOD\n";
    const std::string png = file_part(figure) + "-vs-" + file_part(plan.params[p]) + ".png";
    pngs.push_back(png);
    gp += "set output " + gnuplot_quote(png) + "\n";
    gp += "set title " + gnuplot_quote(figure + " against " + plan.params[p]) + " noenhanced\n";
    gp += "set xlabel " + gnuplot_quote(plan.params[p]) + " noenhanced\nset ylabel " + gnuplot_quote(figure) +
          " noenhanced\n";
    if (numeric) {
      gp += "set xtics autofreq\n";
    } else {
      gp += "set xtics (";
      for (std::size_t level = 0; level < values.size(); ++level)
        gp += (level ? ", " : "") + gnuplot_quote(values[level]) + " " + std::to_string(level);
      gp += ")\n";
    }
    gp += "plot " + block + " using 1:2 with points pt 7 ps 0.8 lc rgb '#1f78b4' title 'runs', " + block +
          "_mean using 1:2 with linespoints lw 2 pt 5 lc rgb '#d95f02' title 'mean'\n";
  }
  return gp;
}

}  // namespace

FigureKind figure_kind(const Gathered& g, const std::string& figure) {
  bool numbers = true, booleans = true, any = false;
  for (const RunState& s : g.runs()) {
    const std::string* text = figure_of(s, figure);
    if (!text) continue;
    any = true;
    numbers &= number(*text).has_value();
    booleans &= *text == "true" || *text == "false";
  }
  if (!any) return FigureKind::kText;
  return booleans ? FigureKind::kBoolean : numbers ? FigureKind::kNumber : FigureKind::kText;
}

std::vector<Spread> spreads(const Plan& plan, const Gathered& g, const std::string& figure) {
  std::vector<Spread> out;
  std::map<std::vector<std::string>, std::vector<std::size_t>> members;
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    const auto& values = plan.runs[k].values;
    if (!members.count(values)) out.push_back(Spread{values});
    members[values].push_back(k);
  }
  for (Spread& s : out) {
    std::vector<std::pair<double, int>> xs;
    for (std::size_t k : members[s.values]) {
      const std::string* text = figure_of(g.runs()[k], figure);
      if (!text) continue;
      s.trues += *text == "true";
      if (const auto v = number(*text)) xs.push_back({*v, plan.runs[k].index});
      else if (*text == "true" || *text == "false") ++s.runs;
    }
    if (xs.empty()) continue;
    s.runs = int(xs.size());
    s.low = s.high = xs.front().first;
    s.low_run = s.high_run = xs.front().second;
    double sum = 0;
    for (const auto& [v, run] : xs) {
      sum += v;
      if (v < s.low) s.low = v, s.low_run = run;
      if (v > s.high) s.high = v, s.high_run = run;
    }
    s.mean = sum / double(xs.size());
    double squares = 0;
    for (const auto& [v, run] : xs) squares += (v - s.mean) * (v - s.mean);
    s.sd = xs.size() > 1 ? std::sqrt(squares / double(xs.size() - 1)) : std::nan("");
  }
  return out;
}

std::string write_summary(const Plan& plan, const Gathered& g, const std::string& dir) {
  const Tally t = g.tally();
  const SweepTable table = sweep_table(plan, g);
  std::ostringstream out;
  out << "# Sweep of " << fs::path(plan.scene).filename().string() << "\n\n" << plan_line(plan) << "\n\n";
  out << t.ok << " ok, " << t.failed << " failed, " << t.cancelled << " cancelled";
  if (t.running + t.waiting) out << ", " << t.running + t.waiting << " not finished";
  out << ".\n";
  auto seed_of = [&](int run) { return std::to_string(plan.runs[std::size_t(run - 1)].seed); };
  if (t.failed + t.cancelled) {
    out << "\n| run |";
    for (const std::string& p : plan.params) out << " " << md(p) << " |";
    out << " seed | status | error |\n|---|";
    for (std::size_t p = 0; p < plan.params.size(); ++p) out << "---|";
    out << "---|---|---|\n";
    for (std::size_t k = 0; k < plan.runs.size(); ++k) {
      const RunState& s = g.runs()[k];
      if (s.outcome.kind == Outcome::kOk || (s.outcome.kind != Outcome::kFailed && s.status != "cancelled")) continue;
      out << "| " << plan.runs[k].index << " |";
      for (const std::string& v : plan.runs[k].values) out << " " << md(v) << " |";
      out << " " << plan.runs[k].seed << " | " << s.status << " | " << md(s.outcome.error) << " |\n";
    }
  }
  out << "\nPer combination of parameter values, over its seeds and the runs that finished well: the mean, the "
         "spread (sd, the sample standard deviation) and the runs with the lowest and highest value; whether "
         "lower or higher is better depends on the figure. The figures are those the scene reported "
         "(`tendril.report`), the columns of `sweep.csv`.\n";

  std::vector<std::string> text_figures, constant_figures;
  std::string data, gp;
  std::vector<std::string> pngs;
  for (const std::string& figure : table.metrics) {
    const FigureKind kind = figure_kind(g, figure);
    if (kind == FigureKind::kText) {
      text_figures.push_back(figure);
      continue;
    }
    // A figure no parameter or seed changes says nothing per combination.
    std::set<std::string> seen;
    for (const RunState& s : g.runs())
      if (const std::string* text = figure_of(s, figure)) seen.insert(*text);
    if (seen.size() == 1) {
      constant_figures.push_back(md(figure) + " = " + md(*seen.begin()));
      continue;
    }
    out << "\n## " << md(figure) << "\n\n|";
    for (const std::string& p : plan.params) out << " " << md(p) << " |";
    out << (kind == FigureKind::kNumber ? " runs | mean | sd | lowest | highest |\n|" : " runs | true |\n|");
    for (std::size_t p = 0; p < plan.params.size(); ++p) out << "---|";
    out << (kind == FigureKind::kNumber ? "---:|---:|---:|---|---|\n" : "---:|---:|\n");
    for (const Spread& s : spreads(plan, g, figure)) {
      out << "|";
      for (const std::string& v : s.values) out << " " << md(v) << " |";
      if (kind == FigureKind::kBoolean) {
        out << " " << s.runs << " | " << s.trues << " of " << s.runs << " |\n";
      } else if (s.runs == 0) {
        out << " 0 | | | | |\n";
      } else {
        out << " " << s.runs << " | " << figure_text(s.mean) << " | " << (std::isnan(s.sd) ? "" : figure_text(s.sd))
            << " | " << figure_text(s.low) << " (run " << s.low_run << ", seed " << seed_of(s.low_run) << ") | "
            << figure_text(s.high) << " (run " << s.high_run << ", seed " << seed_of(s.high_run) << ") |\n";
      }
    }
    if (kind == FigureKind::kNumber && !plan.params.empty()) {
      const std::size_t first = pngs.size();
      gp += figure_plots(plan, g, figure, data, pngs);
      out << "\n";
      for (std::size_t k = first; k < pngs.size(); ++k)
        out << "![" << md(figure) << " against " << md(plan.params[k - first]) << "](plots/" << pngs[k] << ")\n";
    }
  }
  if (!constant_figures.empty()) {
    out << "\nThe same in every run that finished well:";
    for (std::size_t k = 0; k < constant_figures.size(); ++k) out << (k ? ", " : " ") << constant_figures[k];
    out << ".\n";
  }
  if (!text_figures.empty()) {
    out << "\nNot summarised (text):";
    for (const std::string& f : text_figures) out << " " << md(f);
    out << ".\n";
  }
  write_file_atomically(dir + "/summary.md", out.str());

  if (pngs.empty()) return "";
  if (!gnuplot_available()) return "gnuplot not found (Debian: apt-get install gnuplot-nox): no plots in " + dir + "/plots";
  // The plots are drawn in a scratch folder that replaces DIR/plots whole.
  const std::string scratch = dir + "/.plots-tmp", plots = dir + "/plots";
  std::error_code ec;
  fs::remove_all(scratch, ec);
  fs::create_directories(scratch);
  write_file_atomically(scratch + "/plots.gp", "# Written by tendril sweep: each figure against each parameter.\n"
                                               "set terminal pngcairo size 800,560 font 'sans,11'\n"
                                               "set grid lc rgb '#dddddd'\nset key top right\n"
                                               "set offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08\n" +
                                                   data + gp);
  if (std::string failed = run_gnuplot(scratch, "plots.gp", "", "gnuplot.log"); !failed.empty()) return failed;
  fs::remove_all(plots, ec);
  fs::rename(scratch, plots, ec);
  if (ec) return "cannot move " + scratch + " to " + plots + ": " + ec.message();
  return "";
}

}  // namespace tendril::sweep
