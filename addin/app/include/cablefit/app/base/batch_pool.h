// `--jobs N` for the batch commands: independent work items (cases, input files) at most N at a
// time, in index order of starting, on the core's pool (ParallelForEach), and one line per
// failed item.
#pragma once

#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace cablefit::addin {

/// The cores this process may run on: its CPU affinity (`taskset`, a container's cpuset) where
/// the system says, else the hardware concurrency; at least 1. More threads than that only take
/// turns on the same cores.
int UsableCores();

/// The worker count for a `--jobs` value: `requested` if > 0, else UsableCores(); never more
/// than `items` (and at least 1).
int ResolveJobs(int requested, int items);

/// Calls `work(i)` for every i in [0, items) on `jobs` threads, the calling one included
/// (jobs <= 1: on the calling thread, in order). Items are taken in increasing i as threads
/// become free. An exception escaping `work(i)` is stored at index i of the result (null where
/// the item succeeded) and does not stop the other items; a cancel inside one item (its own
/// CancellationScope) does not cancel the next. Work items must not share mutable state
/// without locking.
std::vector<std::exception_ptr> RunBatch(int items, int jobs, const std::function<void(int)>& work);

/// The one-line problem of an item's exception, one form per error tier: a FileError's problem
/// without its file name (the caller names the file); "internal error: ..." for a UsageError (a
/// bug in cablefit, not in the input); "cancelled" / "timed out after N s" for Cancelled; another
/// exception's what().
std::string ErrorText(const std::exception_ptr& e);

}  // namespace cablefit::addin
