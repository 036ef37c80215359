#include "vsim/core/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace vsim {

void parallelFor(std::size_t count, const std::function<void(std::size_t index)>& body,
                 const std::function<void(std::size_t itemsDone)>& onCallerItemDone, unsigned threads)
{
    if (count == 0)
        return;
    if (threads == 0)
        threads = std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, count));

    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};
    std::atomic<bool> stop{false};
    std::exception_ptr firstError;
    std::mutex errorMutex;

    auto work = [&](bool isCaller) {
        try
        {
            while (!stop.load(std::memory_order_relaxed))
            {
                const std::size_t index = next.fetch_add(1);
                if (index >= count)
                    break;
                body(index);
                const std::size_t finished = done.fetch_add(1) + 1;
                if (isCaller && onCallerItemDone)
                    onCallerItemDone(finished);
            }
        }
        catch (...)
        {
            stop.store(true);
            const std::lock_guard<std::mutex> lock(errorMutex);
            if (!firstError)
                firstError = std::current_exception();
        }
    };

    std::vector<std::thread> helpers;
    helpers.reserve(threads - 1);
    for (unsigned t = 1; t < threads; ++t)
        helpers.emplace_back(work, false);
    work(true);
    for (std::thread& helper : helpers)
        helper.join();
    if (firstError)
        std::rethrow_exception(firstError);
}

} // namespace vsim
