#include "cablefit/core/base/parallel_for.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "cablefit/core/base/cancellation.h"

namespace cablefit {

void ParallelFor(int n, int threads, const std::function<void(int)>& work) {
  const int workers = std::min(threads, n);
  if (workers <= 1) {
    for (int i = 0; i < n; ++i) work(i);
    return;
  }
  std::mutex mutex;
  int next = 0;
  bool failed = false;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(n));
  const CancellationState parent = CurrentCancellation();
  auto worker = [&] {
    const CancellationScope scope(parent);
    for (;;) {
      int i;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (failed || next == n) return;
        i = next++;
      }
      try {
        work(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        errors[static_cast<std::size_t>(i)] = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
  worker();  // the calling thread takes its share
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace cablefit
