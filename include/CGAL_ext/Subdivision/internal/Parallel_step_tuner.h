// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Which steps of a refinement run with threads, learnt from the steps this
// process has timed: the level size above which threads pay for themselves
// differs more than tenfold between machines (how fast a core reads what
// another core wrote, how fast sleeping threads wake), so no constant fits
// them all. The serial and the parallel passes give the same bits, so the
// choice changes the time only, never the result.

#ifndef CGAL_EXT_SUBDIVISION_INTERNAL_PARALLEL_STEP_TUNER_H
#define CGAL_EXT_SUBDIVISION_INTERNAL_PARALLEL_STEP_TUNER_H

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

namespace CGAL_ext {
namespace Subdivision {
namespace internal {

// The size class of a level of n vertices: floor(log2(n)), 0 for n = 0.
inline unsigned size_class(std::uint32_t n)
{
  unsigned c = 0;
  while (n >>= 1)
    ++c;
  return c;
}

constexpr unsigned number_of_size_classes = 32;

// Which size classes one refinement runs with threads, fixed when it
// starts, so that all its stages and the tables made for later steps agree.
struct Parallel_plan
{
  enum Decision : std::int8_t { serial = 0, parallel = 1 };
  std::array<Decision, number_of_size_classes> by_class;
  // The class whose timings the refinement gives the tuner (-1: none).
  int tried = -1;

  Parallel_plan() { by_class.fill(parallel); }
  bool parallel_class(unsigned c) const { return by_class[c] == parallel; }
};

// Per number of threads, the best time per parent vertex of the steps run
// serially and in parallel in each size class, and what they showed.
//
// Planning a refinement (`plan()`), a class where threads may run (the prior
// `runs_in_parallel()` allows them) gets:
// - the verdict of the nearest class that implies one, the gain from
//   threads growing with the level's size: threads won in this class or a
//   smaller one, or lost in this class or a larger one (a win and a loss at
//   the same distance: the win, as where nothing is known);
// - otherwise, if the refinement may try (`try_open_class`) and this is its
//   smallest such class, the class is tried: threads until it has
//   `samples_per_verdict` timings of them, then no threads as often, and the
//   faster then becomes its verdict; the larger classes with no verdict run
//   in parallel meanwhile. Only one class is tried per refinement, the
//   smallest, where a serial try costs least, and only the tried class's
//   timings count, so that the two ways are timed alike. Each way runs
//   several times in a row, not in turn: a step right after one the other
//   way finds its data in another core's cache (on a machine where cores
//   read each other's writes slowly, a serial step after a parallel one
//   took 1.7 times as long as after a serial one), and the best of each
//   way's timings is that of a run that follows its own kind.
// Verdicts are final for the process: timings only become shorter (best
// of), and a verdict taken on a loaded machine stays.
class Parallel_step_tuner
{
public:
  static constexpr unsigned samples_per_verdict = 3;

  // The plan of a refinement on `threads` threads whose steps start from
  // levels of `parents[k]` vertices; `may_run_parallel(n)` is the prior.
  template <class Prior>
  Parallel_plan plan(unsigned threads, const std::vector<std::uint32_t>& parents, const Prior& may_run_parallel,
                     bool try_open_class = true)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const Table& t = table(threads);
    Parallel_plan p;
    for (unsigned c = 0; c < number_of_size_classes; ++c)
      p.by_class[c] = t.inferred(c).value_or(Parallel_plan::parallel);
    for (std::uint32_t n : parents) {
      const unsigned c = size_class(n);
      if (!try_open_class || !may_run_parallel(n) || t.inferred(c))
        continue;
      p.tried = int(c);
      p.by_class[c] = t.samples[c].count[Parallel_plan::parallel] < samples_per_verdict ? Parallel_plan::parallel
                                                                                        : Parallel_plan::serial;
      break;
    }
    return p;
  }

  // A step from a level of `parent_vertices`, of the class a plan tried,
  // took `seconds`.
  void record(unsigned threads, std::uint32_t parent_vertices, bool parallel, double seconds)
  {
    if (parent_vertices == 0)
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    Table& t = table(threads);
    const unsigned c = size_class(parent_vertices);
    Samples& s = t.samples[c];
    const int mode = parallel ? Parallel_plan::parallel : Parallel_plan::serial;
    const double per_vertex = seconds / double(parent_vertices);
    if (per_vertex < s.best[mode])
      s.best[mode] = per_vertex;
    ++s.count[mode];
    if (t.verdict[c] < 0 && s.count[0] >= samples_per_verdict && s.count[1] >= samples_per_verdict)
      t.verdict[c] = s.best[Parallel_plan::parallel] < s.best[Parallel_plan::serial] ? Parallel_plan::parallel
                                                                                       : Parallel_plan::serial;
  }

  // The verdict of class `c` on `threads` threads, if it has one of its own
  // (for tests and the benchmarks' reports).
  int verdict(unsigned threads, unsigned c)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return table(threads).verdict[c];
  }

  // Forgets every timing and verdict (a test that starts from nothing).
  void clear()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    tables_.clear();
  }

private:
  struct Samples
  {
    double best[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    unsigned count[2] = {0, 0};
  };

  struct Table
  {
    std::array<Samples, number_of_size_classes> samples;
    std::array<int, number_of_size_classes> verdict; // -1: none yet

    Table() { verdict.fill(-1); }

    // The verdict implied for class c: from the nearest class that implies
    // one (a win of the threads at c - d, a loss at c + d).
    std::optional<Parallel_plan::Decision> inferred(unsigned c) const
    {
      for (unsigned d = 0; d < number_of_size_classes; ++d) {
        if (d <= c && verdict[c - d] == Parallel_plan::parallel)
          return Parallel_plan::parallel;
        if (c + d < number_of_size_classes && verdict[c + d] == Parallel_plan::serial)
          return Parallel_plan::serial;
      }
      return std::nullopt;
    }
  };

  Table& table(unsigned threads) { return tables_[threads]; }

  std::mutex mutex_;
  std::map<unsigned, Table> tables_;
};

} // namespace internal
} // namespace Subdivision
} // namespace CGAL_ext

#endif // CGAL_EXT_SUBDIVISION_INTERNAL_PARALLEL_STEP_TUNER_H
