// One background thread that runs the frame's simulation steps while the main thread draws the
// frame before them (app.cpp, "the pipeline"). With a software renderer (llvmpipe) the buffer swap
// is raster work on the CPU: stepping and drawing one after the other left one core idle half the
// frame.
//
// Hand-over, not sharing: between start() and wait() the job owns whatever it touches (the world,
// the tools' drag state, the rewind history, the sound stream) and the caller touches none of it;
// the mutex hand-over in start() and wait() orders the two threads' accesses.
#pragma once
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace clothtear::app {

class SimThread {
public:
    // The job's parallel loops use the OpenMP team size of the thread that makes this one (an
    // OpenMP setting is a thread's own: main()'s omp_set_num_threads does not reach a new thread).
    SimThread();
    ~SimThread();
    SimThread(const SimThread&) = delete;
    SimThread& operator=(const SimThread&) = delete;

    // Runs `job` on the thread. At most one job at a time: wait() for the last one first.
    void start(std::function<void()> job);
    // Returns once the job started last has returned (at once if none runs). An exception the job
    // threw is thrown here, on the caller's thread, as it would have been had the job run there.
    void wait();
    bool busy() const;

private:
    void loop(int ompThreads);

    mutable std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::function<void()> job_;
    std::exception_ptr error_; // what the last job threw, for wait()
    bool running_ = false, quit_ = false;
    std::thread thread_; // last: started once the members above exist
};

} // namespace clothtear::app
