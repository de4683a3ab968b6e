#pragma once
// A few threads that share the iterations of a loop with the calling thread, for work whose
// iterations are independent (verifying loop candidates). Iteration i always runs on thread
// i % size(), so per-thread scratch (e.g. one graph matcher each) is reused without locks and
// the results do not depend on timing. Idle threads sleep on a condition variable: an idle
// pool costs no CPU.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace toposlam::mapping {

class WorkerPool {
  public:
    /// Iteration task(i, thread): `thread` in [0, size()), 0 being the caller.
    using Task = std::function<void(std::size_t i, std::size_t thread)>;

    /// `threads` in all, the caller included (1: everything runs in the caller).
    explicit WorkerPool(std::size_t threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    std::size_t size() const { return workers_.size() + 1; }

    /// Runs task(i, i % size()) for every i in [0, n) and returns when all have run. The
    /// first exception thrown by an iteration is rethrown here.
    void run(std::size_t n, const Task& task);

    /// CPU seconds the pool's own threads (not the caller) have spent in tasks so far.
    double workerCpuSeconds() const { return workerCpuSeconds_; }

  private:
    void work(std::size_t thread);
    void runShare(std::size_t thread);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::size_t generation_ = 0;  // incremented for each run
    std::size_t busy_ = 0;        // workers still running the current generation
    bool stopping_ = false;
    const Task* task_ = nullptr;
    std::size_t iterations_ = 0;
    std::exception_ptr error_;
    double workerCpuSeconds_ = 0;
};

}  // namespace toposlam::mapping
