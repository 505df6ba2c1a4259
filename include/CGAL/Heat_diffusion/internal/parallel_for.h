// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_PARALLEL_FOR_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_PARALLEL_FOR_H

#include <algorithm>
#include <cstddef>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Calls f(i) for i in [0, n), in parallel when CGAL is linked with TBB, in ranges of
// at least `grain_size` items. The callers write to disjoint slots only, so the
// sequential and the parallel runs give bit-identical results.
template <typename Function>
void parallel_for(std::size_t n, const Function& f, std::size_t grain_size = 1024)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain_size),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for(std::size_t i = range.begin(); i != range.end(); ++i)
                        f(i);
                    });
#else
  for(std::size_t i = 0; i < n; ++i)
    f(i);
#endif
}

// Calls f() and g(), at the same time when CGAL is linked with TBB. An exception of
// either is thrown once both have ended.
template <typename F, typename G>
void parallel_invoke(const F& f, const G& g)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_invoke(f, g);
#else
  f();
  g();
#endif
}

// The number of parts for work whose parts each need memory of the input's size (so
// that it is not split item by item): one per thread, up to 8 (1 without TBB).
inline std::size_t number_of_parallel_parts()
{
#ifdef CGAL_LINKED_WITH_TBB
  return (std::min)(std::size_t(8), std::size_t((std::max)(1, tbb::this_task_arena::max_concurrency())));
#else
  return 1;
#endif
}

// One scratch object per thread (e.g. the marks of a breadth-first search), made by
// make_scratch() on a thread's first use and kept across calls of
// parallel_for_with_scratch(), so that work split into blocks allocates it once.
template <typename Scratch>
class Per_thread_scratch
{
public:
  template <typename MakeScratch>
  explicit Per_thread_scratch(const MakeScratch& make_scratch)
#ifdef CGAL_LINKED_WITH_TBB
    : scratches_(make_scratch)
#else
    : scratch_(make_scratch())
#endif
  {}
  Scratch& local()
  {
#ifdef CGAL_LINKED_WITH_TBB
    return scratches_.local();
#else
    return scratch_;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<Scratch> scratches_;
#else
  Scratch scratch_;
#endif
};

// As parallel_for, calling f(i, scratch) with the scratch object of the thread.
template <typename Scratch, typename Function>
void parallel_for_with_scratch(std::size_t n, Per_thread_scratch<Scratch>& scratches, const Function& f,
                               std::size_t grain_size = 256)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain_size),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      Scratch& scratch = scratches.local();
                      for(std::size_t i = range.begin(); i != range.end(); ++i)
                        f(i, scratch);
                    });
#else
  Scratch& scratch = scratches.local();
  for(std::size_t i = 0; i < n; ++i)
    f(i, scratch);
#endif
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_PARALLEL_FOR_H
