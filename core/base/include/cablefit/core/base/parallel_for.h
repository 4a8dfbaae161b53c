// Independent pieces of one work item (the starts of a fit) on a few threads, with the same
// result as on one: every piece writes only its own slot, and the pieces are handed out in index
// order. The calling thread's cancellation scope (time limit, cancel) continues in the workers.
#pragma once

#include <functional>

namespace cablefit {

/// Calls `work(i)` for every i in [0, n) on up to `threads` threads (threads <= 1 or n <= 1: on
/// the calling thread, in order). When a call throws, no further index is started and, once the
/// running calls have returned, the exception of the lowest failed index is rethrown.
void ParallelFor(int n, int threads, const std::function<void(int)>& work);

}  // namespace cablefit
