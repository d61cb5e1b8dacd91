// A race that ThreadSanitizer must report, for scripts/tsan.sh: two TBB
// threads add to one plain integer. If it goes unreported, the detector
// cannot see through this TBB, and a clean run of the tests would prove
// nothing.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <thread>

int main()
{
  long shared = 0;
  tbb::task_arena arena(2);
  // 64 chunks of a millisecond each: a second thread joins the loop even on
  // a loaded machine (ThreadSanitizer needs two threads, not overlapping
  // accesses: it reports accesses that no synchronisation orders).
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, 64, 1), [&](const tbb::blocked_range<int>& r) {
      for (int i = r.begin(); i < r.end(); ++i) {
        shared += i;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    });
  });
  return shared == -1 ? 1 : 0;
}
