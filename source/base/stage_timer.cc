// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/base/stage_timer.h>

#include <algorithm>

namespace dealvem
{
  StageTimer::StageTimer()
  {
    clock.start();
  }



  StageTimer::Scope::Scope(StageTimer &timer, const std::string &stage)
    : timer(timer)
  {
    timer.enter(stage);
  }



  StageTimer::Scope::~Scope()
  {
    timer.leave();
  }



  // The stage that ran until now is charged with its time and paused.
  void
  StageTimer::enter(const std::string &stage)
  {
    const double now = clock.wall_time();
    if (!running.empty())
      times[running.back().first] += now - running.back().second;
    times.emplace(stage, 0.);
    running.emplace_back(stage, now);
  }



  // The innermost stage ends; the one it paused runs again.
  void
  StageTimer::leave()
  {
    const double now = clock.wall_time();
    times[running.back().first] += now - running.back().second;
    running.pop_back();
    if (!running.empty())
      running.back().second = now;
  }



  std::map<std::string, double>
  StageTimer::stages() const
  {
    std::map<std::string, double> result = times;
    if (!running.empty())
      result[running.back().first] += clock.wall_time() - running.back().second;
    return result;
  }



  std::map<std::string, double>
  StageTimer::stages_since(const std::map<std::string, double> &earlier) const
  {
    std::map<std::string, double> result = stages();
    for (auto &s : result)
      {
        const auto e = earlier.find(s.first);
        if (e != earlier.end())
          s.second -= e->second;
      }
    return result;
  }



  double
  StageTimer::wall_time() const
  {
    return clock.wall_time();
  }



  std::map<std::string, double>
  StageTimer::breakdown() const
  {
    // (the total is read after the stages, so that it is not the smaller)
    std::map<std::string, double> result = stages();
    double                        sum    = 0;
    for (const auto &s : result)
      sum += s.second;
    const double total     = wall_time();
    result["total"]       = total;
    result["unaccounted"] = std::max(0., total - sum);
    return result;
  }
} // namespace dealvem
