// A small fixed thread pool for the skin/ kernels: runs task i = 0 .. n-1 of
// one job at a time on the workers and the calling thread. A call allocates
// nothing; the work split is chosen by the caller (fixed-size chunks), so a
// kernel's results never depend on how many threads there are.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace m3g::skin {

class ThreadPool {
public:
    /// A pool in which `threads` threads work on a job: threads - 1 workers
    /// plus the caller of run(). threads <= 1 gives a pool that runs
    /// everything on the caller.
    explicit ThreadPool(int threads);
    /// Joins the workers.
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    /// Threads that work on a job (workers + the caller).
    int threadCount() const noexcept { return static_cast<int>(workers_.size()) + 1; }

    /// Calls fn(context, i) for every i in [0, tasks), each exactly once,
    /// spread over the threads, and returns when all have returned. `fn`
    /// must not throw. Calls from several threads at once are safe: a call
    /// made while another job is running runs its tasks on its own thread.
    /// Tasks are claimed one at a time; a worker that has not woken up by
    /// the time every task is claimed (a busy machine) is not waited for.
    void run(std::size_t tasks, void (*fn)(void* context, std::size_t task), void* context) noexcept;

    /// run() with a callable `f(std::size_t task)`; no allocation.
    template <class F>
    void parallelFor(std::size_t tasks, F& f) noexcept {
        run(tasks, [](void* c, std::size_t i) { (*static_cast<F*>(c))(i); }, &f);
    }

    /// The process-wide pool (std::thread::hardware_concurrency() threads),
    /// created on first use.
    static ThreadPool& shared();

private:
    void workerLoop();
    void work() noexcept;

    std::vector<std::thread> workers_;
    std::mutex submit_;  // one job at a time
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    std::uint64_t generation_ = 0;
    bool stop_ = false;
    // The current job.
    void (*fn_)(void*, std::size_t) = nullptr;
    void* context_ = nullptr;
    std::size_t tasks_ = 0;
    std::atomic<std::size_t> next_{0};
    bool open_ = false;        // workers may still join the current job
    std::size_t active_ = 0;   // workers inside the current job
};

}  // namespace m3g::skin
