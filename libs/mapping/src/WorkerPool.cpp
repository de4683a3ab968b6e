#include <toposlam/io/CpuTime.h>
#include <toposlam/mapping/WorkerPool.h>

#include <algorithm>
#include <utility>

namespace toposlam::mapping {

WorkerPool::WorkerPool(std::size_t threads) {
    for (std::size_t t = 1; t < std::max<std::size_t>(threads, 1); ++t)
        workers_.emplace_back([this, t] { work(t); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& w : workers_)
        w.join();
}

void WorkerPool::runShare(std::size_t thread) {
    try {
        for (std::size_t i = thread; i < iterations_; i += size())
            (*task_)(i, thread);
    } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_)
            error_ = std::current_exception();
    }
}

void WorkerPool::run(std::size_t n, const Task& task) {
    if (workers_.empty() || n < 2) {  // nothing to share: no hand-over cost
        for (std::size_t i = 0; i < n; ++i)
            task(i, 0);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        task_ = &task;
        iterations_ = n;
        error_ = nullptr;
        busy_ = workers_.size();
        ++generation_;
    }
    wake_.notify_all();
    runShare(0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return busy_ == 0; });
    task_ = nullptr;
    if (error_)
        std::rethrow_exception(std::exchange(error_, nullptr));
}

void WorkerPool::work(std::size_t thread) {
    std::size_t seen = 0;
    for (;;) {
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_)
                return;
            seen = generation_;
        }
        const double start = io::threadCpuSeconds();
        runShare(thread);
        const double spent = io::threadCpuSeconds() - start;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            workerCpuSeconds_ += spent;
            --busy_;
        }
        done_.notify_one();
    }
}

}  // namespace toposlam::mapping
