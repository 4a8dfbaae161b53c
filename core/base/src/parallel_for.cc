#include "cablefit/core/base/parallel_for.h"

#include <algorithm>
#include <mutex>
#include <optional>
#include <thread>

#include "cablefit/core/base/cancellation.h"

namespace cablefit {
namespace {

enum class OnFailure { kStopStarting, kGoOn };

std::vector<std::exception_ptr> Run(int n, int threads, const std::function<void(int)>& work,
                                    OnFailure on_failure) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(n, 0)));
  const int workers = std::min(threads, n);
  std::mutex mutex;
  int next = 0;
  bool failed = false;
  const CancellationState parent = CurrentCancellation();
  auto take = [&](int* i) {
    const std::lock_guard<std::mutex> lock(mutex);
    if ((failed && on_failure == OnFailure::kStopStarting) || next >= n) return false;
    *i = next++;
    return true;
  };
  auto record = [&](int i) {
    const std::lock_guard<std::mutex> lock(mutex);
    errors[static_cast<std::size_t>(i)] = std::current_exception();
    failed = true;
  };
  // The calling thread runs its items in its own scope, as a serial loop would; a worker thread
  // opens the caller's scope anew for every item.
  auto run_items = [&](bool worker_thread) {
    for (int i; take(&i);) {
      try {
        std::optional<CancellationScope> scope;
        if (worker_thread) scope.emplace(parent);
        work(i);
      } catch (...) {
        record(i);
      }
    }
  };
  if (workers <= 1) {
    run_items(false);
    return errors;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) pool.emplace_back(run_items, true);
  run_items(false);
  for (std::thread& t : pool) t.join();
  return errors;
}

}  // namespace

void ParallelFor(int n, int threads, const std::function<void(int)>& work) {
  for (const std::exception_ptr& e : Run(n, threads, work, OnFailure::kStopStarting))
    if (e) std::rethrow_exception(e);
}

std::vector<std::exception_ptr> ParallelForEach(int n, int threads,
                                                const std::function<void(int)>& work) {
  return Run(n, threads, work, OnFailure::kGoOn);
}

}  // namespace cablefit
