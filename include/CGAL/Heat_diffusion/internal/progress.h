// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_PROGRESS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_PROGRESS_H

#include <CGAL/Heat_diffusion/parameters.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The user's `progress_callback` seen by one stage of a construction: the stage reports
// its own fraction done in [0, 1], which is mapped to its share [begin, end] of the
// whole, so that a construction made of several stages (simplification, eigen solve,
// heat regions) shows one bar that only moves forward. A callback returning false
// cancels: report() then throws a std::runtime_error naming the stage.
//
// Called on the calling thread only (between parallel blocks), so the callback need
// not be thread-safe.
class Progress
{
public:
  Progress() = default;
  explicit Progress(std::function<bool(double)> callback) : callback_(std::move(callback)) {}

  // The part [from, to] (fractions of this stage) of this stage.
  Progress part(double from, double to) const
  {
    Progress p;
    p.callback_ = callback_;
    p.begin_ = begin_ + from * (end_ - begin_);
    p.end_ = begin_ + to * (end_ - begin_);
    return p;
  }

  // Reports the fraction done of this stage; throws if the callback cancels.
  void report(double fraction, const char* stage) const
  {
    if(callback_ && !callback_(overall(fraction)))
      throw std::runtime_error(std::string("CGAL::Heat_diffusion: ") + stage + " cancelled by the progress callback");
  }

  // The same, as the `bool(double)` callable that internal solvers take (empty if
  // there is no callback, so that they skip their progress bookkeeping).
  std::function<bool(double)> as_callback() const
  {
    if(!callback_)
      return {};
    const Progress self = *this;
    return [self](double fraction) { return self.callback_(self.overall(fraction)); };
  }

private:
  // A fraction of this stage as a fraction of the whole.
  double overall(double fraction) const { return begin_ + fraction * (end_ - begin_); }

  std::function<bool(double)> callback_;
  double begin_ = 0., end_ = 1.;
};

// The `progress_callback` of the named parameters `np`, or none.
template <typename NamedParameters>
Progress progress_of(const NamedParameters& np)
{
  return Progress(internal::parameter_value(np, internal_np::progress_callback, std::function<bool(double)>()));
}

// `np` with `progress` (a part of the caller's) as its progress callback.
template <typename NamedParameters>
auto with_progress(const NamedParameters& np, const Progress& progress)
{
  return parameters::combine(np, parameters::progress_callback(progress.as_callback()));
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_PROGRESS_H
