// Tiny helpers over OpenMP: a fixed, deterministic split of [0, n) into one contiguous chunk per
// thread. Kernels scatter into per-thread buffers, so results never depend on thread timing.
#pragma once
#include "float_env.h"

#include <algorithm>
#include <cstddef>
#if CLOTHTEAR_HAVE_OPENMP
#include <omp.h>
#endif

namespace clothtear {

inline int maxThreads() {
#if CLOTHTEAR_HAVE_OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

// Most threads a step uses (per-thread results live in fixed arrays of this size).
inline constexpr int kMaxThreadSlots = 64;

// Waits for every thread of the enclosing parallelRegion (call it from all of them or from none).
inline void parallelBarrier(int threads) {
#if CLOTHTEAR_HAVE_OPENMP
    if (threads > 1) {
#pragma omp barrier
    }
#else
    (void)threads;
#endif
}

struct Chunk {
    size_t begin, end;
};
inline Chunk chunkOf(size_t n, int thread, int threads) {
    const size_t per = (n + threads - 1) / threads;
    const size_t b = std::min(n, per * thread);
    return {b, std::min(n, b + per)};
}

// Runs body(thread, threads) on every thread of a parallel region (or once, serially). Small
// problems run serially: forking threads costs more than a few thousand items.
inline constexpr size_t kParallelWork = 4096; // smallest amount of work parallelRegion forks for

template <class Body> void parallelRegion(size_t work, int threads, Body&& body) {
#if CLOTHTEAR_HAVE_OPENMP
    if (threads > 1 && work >= kParallelWork) {
        const unsigned callerFlush = FlushSubnormals::callerFlushBits();
#pragma omp parallel num_threads(threads)
        {
            // Each thread's own MXCSR (float_env.h); the caller's thread is thread 0.
            const int t = omp_get_thread_num();
            const FlushSubnormals flush = t == 0 ? FlushSubnormals() : FlushSubnormals::onWorker(callerFlush);
            body(t, omp_get_num_threads());
        }
        return;
    }
#endif
    (void)threads;
    (void)work;
    body(0, 1);
}

} // namespace clothtear
