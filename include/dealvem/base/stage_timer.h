// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_base_stage_timer_h
#define dealvem_base_stage_timer_h

#include <deal.II/base/timer.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dealvem
{
  /**
   * The wall-time breakdown of a run of the program by its stages (mesh,
   * setup, assembly, solve, postprocessing, verification, output, ...), for
   * the `timings` of the JSON summaries.
   *
   * The stages never overlap: a stage entered while another one runs
   * pauses that one until it is left (the inner stage's time is not also
   * the outer one's), so the times of the stages add up to the wall time
   * spent in them. breakdown() adds the wall time since the timer was
   * made (`total`) and what no stage covers (`unaccounted`), so that a user
   * sees where the run's time went and how much of it the stages explain.
   *
   * @code
   *   StageTimer timer;
   *   {
   *     StageTimer::Scope s(timer, "assembly");
   *     ...
   *   }
   *   for (const auto &[stage, seconds] : timer.breakdown()) ...
   * @endcode
   */
  class StageTimer
  {
  public:
    /// Starts the wall clock of the run.
    StageTimer();

    /// Runs the stage @p stage for the lifetime of the object.
    class Scope
    {
    public:
      /// Enters @p stage of @p timer, pausing the stage that runs.
      Scope(StageTimer &timer, const std::string &stage);
      /// Leaves the stage; the one it paused runs again.
      ~Scope();
      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      StageTimer &timer;
    };

    /// The wall time of each stage entered so far, seconds (a stage that
    /// runs now with the time it has run so far).
    std::map<std::string, double>
    stages() const;

    /// stages() less the times @p earlier of an earlier call (the stages of
    /// a part of the run, e.g. one refinement cycle).
    std::map<std::string, double>
    stages_since(const std::map<std::string, double> &earlier) const;

    /// The wall time since the timer was made, seconds.
    double
    wall_time() const;

    /// stages(), `total` (wall_time()) and `unaccounted` (`total` minus
    /// the sum of the stages; not below zero).
    std::map<std::string, double>
    breakdown() const;

  private:
    void
    enter(const std::string &stage);
    void
    leave();

    dealii::Timer                 clock;
    std::map<std::string, double> times;
    /// The stages entered and not left, innermost last, each with the
    /// clock's time when it last started to run (only the last runs).
    std::vector<std::pair<std::string, double>> running;
  };
} // namespace dealvem

#endif
