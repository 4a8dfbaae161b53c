// Independent work items on a few threads with the same result as on one: every item writes only
// its own slot, and the items are handed out in index order. One pool serves both uses: the
// pieces of one work item (the starts of a fit: the first failure ends them all) and the items
// of a batch (cases, input files: each fails on its own). The calling thread takes its share.
// The calling thread's cancellation scope (time limit, cancel) continues in the worker threads,
// one scope per item, so that a cancel inside one item does not leak into the next item a
// worker takes (cancellation.h).
#pragma once

#include <exception>
#include <functional>
#include <vector>

namespace cablefit {

/// Calls `work(i)` for every i in [0, n) on up to `threads` threads (threads <= 1 or n <= 1: on
/// the calling thread, in order). When a call throws, no further index is started and, once the
/// running calls have returned, the exception of the lowest failed index is rethrown.
void ParallelFor(int n, int threads, const std::function<void(int)>& work);

/// Like ParallelFor, but every index runs whatever the others do: the exception escaping
/// `work(i)` is returned at index i (null where the call returned), and nothing is rethrown.
std::vector<std::exception_ptr> ParallelForEach(int n, int threads,
                                                const std::function<void(int)>& work);

}  // namespace cablefit
