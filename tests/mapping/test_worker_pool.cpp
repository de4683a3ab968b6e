// WorkerPool: every iteration runs once, on the thread the contract names, and errors reach
// the caller.
#include <gtest/gtest.h>
#include <toposlam/mapping/WorkerPool.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

using toposlam::mapping::WorkerPool;

TEST(WorkerPool, RunsEveryIterationOnceOnItsThread) {
    for (std::size_t threads : {1u, 2u, 3u}) {
        WorkerPool pool(threads);
        ASSERT_EQ(pool.size(), threads);
        for (std::size_t n : {0u, 1u, 2u, 7u, 100u}) {  // several runs reuse the threads
            std::vector<int> runs(n, 0);
            std::vector<std::size_t> thread(n, 99);
            std::vector<std::thread::id> id(n);
            pool.run(n, [&](std::size_t i, std::size_t t) {
                ++runs[i];
                thread[i] = t;
                id[i] = std::this_thread::get_id();
            });
            for (std::size_t i = 0; i < n; ++i) {
                EXPECT_EQ(runs[i], 1) << "iteration " << i;
                if (n >= 2) {
                    EXPECT_EQ(thread[i], i % threads);
                    // Thread 0 is the caller; the others are not.
                    EXPECT_EQ(id[i] == std::this_thread::get_id(), i % threads == 0);
                }
            }
        }
    }
}

TEST(WorkerPool, RethrowsAnIterationsErrorAndStaysUsable) {
    WorkerPool pool(2);
    EXPECT_THROW(pool.run(4,
                          [](std::size_t i, std::size_t) {
                              if (i == 3)  // on the worker thread
                                  throw std::runtime_error("iteration 3 failed");
                          }),
                 std::runtime_error);
    std::atomic<int> count{0};
    pool.run(5, [&](std::size_t, std::size_t) { ++count; });
    EXPECT_EQ(count.load(), 5);
}
