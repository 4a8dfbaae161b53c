#include "cablefit/app/base/batch_pool.h"

#include <algorithm>
#include <new>
#include <thread>

#ifdef __linux__
#include <sched.h>
#endif

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"

namespace cablefit::addin {

int UsableCores() {
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
#endif
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int ResolveJobs(int requested, int items) {
  int jobs = requested > 0 ? requested : UsableCores();
  jobs = std::min(std::max(jobs, 1), std::max(items, 1));
  return jobs;
}

std::vector<std::exception_ptr> RunBatch(int items, int jobs,
                                         const std::function<void(int)>& work) {
  return ParallelForEach(items, jobs, work);
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
