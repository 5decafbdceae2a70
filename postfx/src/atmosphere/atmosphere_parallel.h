// A parallel loop for the atmosphere's CPU tables (atmosphere_reference.cpp, atmosphere_orders.cpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace postfx::atmosphere {

// Runs task(i) for i in [0, count) on `threads` threads (0: all hardware threads).
template <class Task>
void parallelFor(uint32_t count, uint32_t threads, const Task& task) {
    std::atomic<uint32_t> next{0};
    auto work = [&] {
        for (uint32_t i; (i = next.fetch_add(1)) < count;)
            task(i);
    };
    threads = std::min(threads ? threads : std::max(1u, std::thread::hardware_concurrency()), count);
    std::vector<std::thread> pool;
    try {
        for (uint32_t t = 1; t < threads; ++t)
            pool.emplace_back(work);
    } catch (const std::exception&) {
        // Fewer threads than asked for: the ones running (and this one) do all the work.
    }
    work();
    for (std::thread& t : pool)
        t.join();
}

}  // namespace postfx::atmosphere
