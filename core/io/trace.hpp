#pragma once
// The replayable half of the journal: every change a scene made to a model,
// primitive by primitive, with the solver steps in between, as text lines
// with exact (hexadecimal) numbers. Replaying it on an empty model gives the
// same model bit for bit, because every operation and step is deterministic.
//
//   particle X Y Z               beam CLOSED EA EI T0 MASS P0 P1 ...
//   cable A B EA EI T0 MASS REST beam_from P DX DY DZ N EA EI T0 MASS
//   quad_grid ROWS COLS EA EI T0 MASS P...   patch EA EI T0 MASS A B C D ...
//   delete_particle P  merge P...  explode P  explode_from P B  delete B  extend B END P
//   insert A B  remove_from_beam P  lock P BITS  passive P 0|1  role P R  load P X Y Z
//   mass P KG  position P X Y Z  gravity X Y Z  settings KEY=VALUE ...
//   section6 B GJ EIy EIz   formulation B 3|6   orientation P W X Y Z
//   formulation B bars | form SW SF A B C ... | analysis SW SF DXX DXY DYX DYY G A B C ...
//     (a patch: bars, or CST triangles A B C with A-B along the warp)
//   torque P X Y Z   steps N   newton_steps N (steps the integrator "auto"
//   took as Newton's, in a run)   failed_step [as=newton] (a step that threw,
//   Newton's for "auto": replayed, it must fail the same way)
//   open PATH (a model database)   # comment
// Each line is a command of command/ (docs/commands.md lists their forms);
// command/replay.hpp replays a trace.
#include <iosfwd>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/solver.hpp"

namespace tendril {

class Trace {
 public:
  // Records one operation line; solver steps taken since the last line are
  // written first as "steps N".
  void record(const Solver& s, const std::string& line);
  // Lines recorded after a mark are dropped by rewind (a rolled-back production).
  struct Mark {
    std::size_t lines;
    std::uint64_t steps;
    std::size_t failures;
  };
  Mark mark() const { return {lines_.size(), traced_steps_, traced_failures_}; }
  void rewind(Mark m) {
    lines_.resize(m.lines);
    traced_steps_ = m.steps;
    traced_failures_ = m.failures;
  }
  // All lines, with the steps (and failed steps) still pending at `s`.
  std::vector<std::string> lines(const Solver& s) const;
  // The lines up to mark m, then what `s` did after it up to its `steps`-th
  // step and its `failures`-th failed step: a place in a session that lies
  // after the mark's last line (the studio's timeline).
  std::vector<std::string> lines_until(const Solver& s, Mark m, std::uint64_t steps, std::size_t failures) const;
  // The recorded lines one by one (without the pending steps).
  std::size_t size() const { return lines_.size(); }
  const std::string& line(std::size_t k) const { return lines_[k]; }

  static std::string number(double x);  // exact: "%a"
  static std::string vec(const Vec3& v);

 private:
  // Appends "steps N", "newton_steps N" and "failed_step" lines for the
  // steps, the steps "auto" took as Newton's (Solver::auto_newton_steps) and
  // the failed steps (Solver::failed_steps) after `steps` and `failures` up
  // to `steps_to` and `failures_to`, and advances both.
  static void pending(const Solver& s, std::uint64_t steps_to, std::size_t failures_to, std::uint64_t& steps,
                      std::size_t& failures, std::vector<std::string>& out);
  // The steps from `steps` to `to`, split where "auto" took Newton's.
  static void steps_lines(const Solver& s, std::uint64_t steps, std::uint64_t to, std::vector<std::string>& out);

  std::vector<std::string> lines_;
  std::uint64_t traced_steps_ = 0;
  std::size_t traced_failures_ = 0;
};

}  // namespace tendril
