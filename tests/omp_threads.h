// The OpenMP thread count of a scope (tests that compare one thread with two): set on
// construction, the one before restored on destruction. Without OpenMP it does nothing.
#pragma once
#if CLOTHTEAR_HAVE_OPENMP
#include <omp.h>
#endif

namespace clothtear::test {

class OmpThreads {
public:
    explicit OmpThreads(int threads) {
#if CLOTHTEAR_HAVE_OPENMP
        before_ = omp_get_max_threads();
        omp_set_num_threads(threads);
#else
        (void)threads;
#endif
    }
    ~OmpThreads() {
#if CLOTHTEAR_HAVE_OPENMP
        omp_set_num_threads(before_);
#endif
    }
    OmpThreads(const OmpThreads&) = delete;
    OmpThreads& operator=(const OmpThreads&) = delete;

private:
    int before_ = 1;
};

} // namespace clothtear::test
