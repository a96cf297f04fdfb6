#include <m3g/skin/ThreadPool.h>

#include <algorithm>

namespace m3g::skin {

ThreadPool::ThreadPool(int threads) {
    const int workers = std::max(threads, 1) - 1;
    workers_.reserve(static_cast<std::size_t>(workers));
    for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_) t.join();
}

ThreadPool& ThreadPool::shared() {
    static ThreadPool pool(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
    return pool;
}

void ThreadPool::work() noexcept {
    for (;;) {
        const std::size_t i = next_.fetch_add(1, std::memory_order_relaxed);
        if (i >= tasks_) return;
        fn_(context_, i);
    }
}

void ThreadPool::workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            // A job the caller has already closed (it ran out of tasks before
            // this thread got a CPU) is not touched: its fields may be the
            // next job's by now.
            if (!open_) continue;
            ++active_;
        }
        work();
        {
            std::lock_guard lock(mutex_);
            if (--active_ != 0) continue;
        }
        done_.notify_one();
    }
}

void ThreadPool::run(std::size_t tasks, void (*fn)(void*, std::size_t), void* context) noexcept {
    if (tasks == 0) return;
    std::unique_lock submit(submit_, std::try_to_lock);
    if (workers_.empty() || tasks == 1 || !submit.owns_lock()) {
        for (std::size_t i = 0; i < tasks; ++i) fn(context, i);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        fn_ = fn;
        context_ = context;
        tasks_ = tasks;
        next_.store(0, std::memory_order_relaxed);
        open_ = true;
        ++generation_;
    }
    wake_.notify_all();
    work();
    // Every task has been claimed. Close the job, then wait only for the
    // workers that joined it (they may still be running a claimed task): a
    // worker that has not woken yet (on a busy machine it can take
    // milliseconds to get a CPU) is not waited for, it finds the job closed.
    std::unique_lock lock(mutex_);
    open_ = false;
    done_.wait(lock, [&] { return active_ == 0; });
}

}  // namespace m3g::skin
