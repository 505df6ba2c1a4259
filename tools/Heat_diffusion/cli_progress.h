// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Following the stages of a run: their wall-clock timings (for the JSON summary) and a
// progress bar on stderr.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_PROGRESS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_PROGRESS_H

#include "cli_json.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

// Wall-clock timings of the stages of a run, in milliseconds, in order.
class Stage_timer
{
public:
  void start() { begin_ = std::chrono::steady_clock::now(); }
  void stop(const std::string& stage)
  {
    const auto end = std::chrono::steady_clock::now();
    stages_.emplace_back(stage, std::chrono::duration<double, std::milli>(end - begin_).count());
    begin_ = end;
  }
  const std::vector<std::pair<std::string, double> >& stages() const { return stages_; }

private:
  std::chrono::steady_clock::time_point begin_ = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, double> > stages_;
};

inline Json_object timings_json(const Stage_timer& timer)
{
  Json_object o;
  for(const auto& stage : timer.stages())
    o.number(stage.first, stage.second);
  return o;
}

// A progress bar on stderr: shown when stderr is a terminal and not --quiet, and only
// once the work has lasted a second (short work draws nothing). The environment
// variable HEAT_DIFFUSION_PROGRESS=always shows it at once whatever stderr is (for
// tests), =never hides it.
class Progress_bar
{
public:
  Progress_bar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled)
  {
    const char* mode = std::getenv("HEAT_DIFFUSION_PROGRESS");
    const std::string m = mode ? mode : "";
    if(m == "never")
      enabled_ = false;
    else if(m == "always")
      delay_ = 0.;
    else
      enabled_ = enabled_ && isatty(STDERR_FILENO);
  }
  ~Progress_bar() { finish(); }
  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  // Called with the fraction done, in [0, 1]; always returns true (never cancels).
  bool operator()(double fraction)
  {
    if(!enabled_)
      return true;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if(!shown_ && elapsed < delay_)
      return true;
    const int percent = int(100 * (std::max)(0., (std::min)(1., std::isfinite(fraction) ? fraction : 0.)));
    if(percent != last_)
    {
      last_ = percent;
      shown_ = true;
      std::cerr << "\r" << label_ << " [" << std::string(std::size_t(percent / 5), '#')
                << std::string(std::size_t(20 - percent / 5), ' ') << "] " << percent << "%" << std::flush;
    }
    return true;
  }
  // Clears the bar from the terminal line.
  void finish()
  {
    if(shown_)
      std::cerr << "\r" << std::string(label_.size() + 30, ' ') << "\r" << std::flush;
    shown_ = false;
    last_ = -1;
  }

private:
  std::string label_;
  bool enabled_;
  double delay_ = 1.;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool shown_ = false;
  int last_ = -1;
};

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_PROGRESS_H
