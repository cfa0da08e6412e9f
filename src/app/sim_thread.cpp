#include "sim_thread.h"

#include <cassert>
#include <utility>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace clothtear::app {

namespace {
int callerOmpThreads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}
} // namespace

SimThread::SimThread() : thread_([this, n = callerOmpThreads()] { loop(n); }) {}

SimThread::~SimThread() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void SimThread::start(std::function<void()> job) {
    {
        std::lock_guard lock(mutex_);
        assert(!running_ && "SimThread::start while a job runs: wait() first");
        job_ = std::move(job);
        running_ = true;
    }
    wake_.notify_one();
}

void SimThread::wait() {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return !running_; });
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

bool SimThread::busy() const {
    std::lock_guard lock(mutex_);
    return running_;
}

void SimThread::loop(int ompThreads) {
#ifdef _OPENMP
    omp_set_num_threads(ompThreads > 0 ? ompThreads : 1);
#else
    (void)ompThreads;
#endif
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return running_ || quit_; });
        if (quit_ && !running_) return;
        std::function<void()> job = std::move(job_);
        lock.unlock();
        std::exception_ptr error;
        try {
            job();
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        error_ = error;
        running_ = false;
        done_.notify_all();
    }
}

} // namespace clothtear::app
