#pragma once

#include <cstddef>
#include <functional>

namespace vsim {

/// Runs body(index) for every index in [0, count) on up to `threads` threads (0: one per hardware thread),
/// handing out indices one at a time so uneven items balance. The calling thread works too, and only it calls
/// `onCallerItemDone(itemsDoneSoFar)` after each item it finishes: report progress and check cancellation there
/// (Progress sinks need not be thread-safe). The first exception thrown by `body` or `onCallerItemDone` stops
/// the hand-out of new indices and is rethrown here after every thread has finished.
/// Results must not depend on the thread count: seed per index, write to per-index places.
void parallelFor(std::size_t count, const std::function<void(std::size_t index)>& body,
                 const std::function<void(std::size_t itemsDone)>& onCallerItemDone = {}, unsigned threads = 0);

} // namespace vsim
