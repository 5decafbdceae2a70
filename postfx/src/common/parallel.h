// A parallel loop for the CPU references and tables: independent tasks shared out over threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace postfx::common {

// Runs task(i) for i in [0, count) on `threads` threads (0: all hardware threads). The tasks must be
// independent, so the result does not depend on how they are shared out. If the system gives fewer
// threads than asked for, the ones running (and this one) do all the work.
template <class Index, class Task>
void parallelFor(Index count, uint32_t threads, const Task& task) {
    std::atomic<Index> next{0};
    auto work = [&] {
        for (Index i; (i = next.fetch_add(1)) < count;)
            task(i);
    };
    const uint64_t wanted = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
    threads = uint32_t(std::min<uint64_t>(wanted, std::max<uint64_t>(count, 1)));
    std::vector<std::thread> pool;
    try {
        pool.reserve(threads - 1);
        for (uint32_t t = 1; t < threads; ++t)
            pool.emplace_back(work);
    } catch (const std::exception&) {
    }
    work();
    for (std::thread& t : pool)
        t.join();
}

}  // namespace postfx::common
