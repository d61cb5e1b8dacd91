// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// How the C library's heap treats the large arrays of the benchmarks, fixed
// for a whole run so that the order of the benchmarks does not matter
// (glibc's default mmap threshold adapts to what was freed before):
//  cold: every block of 128 KiB or more is a fresh mapping, returned on free,
//        so each run touches new pages, as the only run of a process does;
//  warm: no mappings and no trimming, so a run reuses the pages of the one
//        before, as in a program that works repeatedly.
// Trimming is turned off with -1 (no limit), not INT_MAX: the largest cases
// free more than 2 GiB at once, which INT_MAX would still hand back to the
// system, so that every "warm" run would fault all its pages in again.

#ifndef CGAL_EXT_BENCH_HEAP_MODES_H
#define CGAL_EXT_BENCH_HEAP_MODES_H

#include <malloc.h>

enum class Heap_mode { cold, warm };

inline void set_heap_mode(Heap_mode mode)
{
  if (mode == Heap_mode::cold) {
    mallopt(M_MMAP_MAX, 65536);
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024);
    malloc_trim(0);
  } else {
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
  }
}

#endif // CGAL_EXT_BENCH_HEAP_MODES_H
