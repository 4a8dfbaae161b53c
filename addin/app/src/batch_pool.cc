#include "cablefit/app/batch_pool.h"

#include "cablefit/core/base/errors.h"

#include <algorithm>
#include <atomic>
#include <new>
#include <thread>

namespace cablefit::addin {

int ResolveJobs(int requested, int items) {
  int jobs = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
  jobs = std::min(std::max(jobs, 1), std::max(items, 1));
  return jobs;
}

std::vector<std::exception_ptr> RunBatch(int items, int jobs,
                                         const std::function<void(int)>& work) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(items, 0)));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i = next++; i < items; i = next++) {
      try {
        work(i);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
  };
  const int threads = std::min(std::max(jobs, 1), std::max(items, 1));
  if (threads <= 1) {
    worker();
    return errors;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  return errors;
}

std::string ErrorText(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const FileError& fe) {
    return fe.problem();
  } catch (const UsageError& ex) {
    return std::string("internal error: ") + ex.what();
  } catch (const std::bad_alloc&) {
    return "out of memory";
  } catch (const std::exception& ex) {
    return OneLine(ex.what());
  } catch (...) {
    return "unknown error";
  }
}

}  // namespace cablefit::addin
