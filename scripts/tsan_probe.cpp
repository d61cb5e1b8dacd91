// A race that ThreadSanitizer must report, for scripts/tsan.sh: two TBB
// threads add to one plain integer. If it goes unreported, the detector
// cannot see through this TBB, and a clean run of the tests would prove
// nothing.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

int main()
{
  long shared = 0;
  tbb::task_arena arena(2);
  arena.execute([&] { tbb::parallel_for(0, 100000, [&](int i) { shared += i; }); });
  return shared == -1 ? 1 : 0;
}
