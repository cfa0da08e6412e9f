// The floating-point environment of the step: subnormal numbers flushed to zero.
//
// Why: a cloth lying in a coordinate plane (every scene's curtain and sheet start in z = 0) keeps
// that coordinate at exactly 0 until something pushes it out of the plane (the drag tool's hand, a
// ball, wind); the damping then lets the offsets and their velocities decay through the subnormal
// range (below 1.2e-38), where every x86 operation on them takes a microcode assist of about a
// hundred cycles. Measured (bench/README.md, "Subnormal numbers in the step"): the window's 128 x 128
// curtain, saved four frames into the drag `assets/screenshots/tear.txt`, had 503 particles with a
// subnormal z and 430 with a subnormal z velocity, and its spring phase took 0.26 ms a sub-step on
// one thread against 0.14 for the same cloth without them. A subnormal offset (1e-38 m) has no
// physical meaning, so the step flushes them: results differ from the unflushed step only where
// such a number was produced, and stay deterministic.
//
// FlushSubnormals sets the x86 MXCSR flags FTZ (results that would be subnormal are 0) and DAZ
// (subnormal inputs are read as 0) for its scope and restores the caller's flags after it, so
// nothing outside the step (the app's renderer, the tests' arithmetic) sees a change. Every thread
// that runs step code needs it: World::step and World::substep on the caller's thread,
// parallelRegion (parallel.h) on each OpenMP thread. Elsewhere (no SSE) it does nothing.
#pragma once
#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#define CLOTHTEAR_HAVE_MXCSR 1
#endif

namespace clothtear {

class FlushSubnormals {
public:
#if CLOTHTEAR_HAVE_MXCSR
    static constexpr unsigned kFlushBits = 0x8000 | 0x0040; // FTZ | DAZ

    // Flushes until the end of the scope, then restores this thread's flags.
    FlushSubnormals() : FlushSubnormals(_mm_getcsr()) {}
    // The same on an OpenMP thread other than the caller's (parallel.h): it ends with the caller's
    // flush bits from outside every step (callerFlushBits), not with the ones it found. A worker the
    // pool started inside a step inherited the step's flags from the thread that started it, and
    // would otherwise keep them after the step.
    static FlushSubnormals onWorker(unsigned callerBits) {
        return FlushSubnormals((_mm_getcsr() & ~kFlushBits) | (callerBits & kFlushBits));
    }
    ~FlushSubnormals() {
        if (outermost_) depth() = 0;
        if (_mm_getcsr() != restore_) _mm_setcsr(restore_);
    }
    // This thread's flush bits outside every FlushSubnormals scope on it.
    static unsigned callerFlushBits() { return (depth() ? outer() : _mm_getcsr()) & kFlushBits; }

private:
    explicit FlushSubnormals(unsigned restore) : restore_(restore), outermost_(depth() == 0) {
        const unsigned now = _mm_getcsr();
        if (outermost_) {
            depth() = 1;
            outer() = now;
        }
        if ((now | kFlushBits) != now) _mm_setcsr(now | kFlushBits);
    }
    static unsigned& depth() {
        thread_local unsigned d = 0;
        return d;
    }
    static unsigned& outer() {
        thread_local unsigned o = 0;
        return o;
    }
    unsigned restore_;
    bool outermost_;

public:
#else
    FlushSubnormals() = default;
    static FlushSubnormals onWorker(unsigned) { return {}; }
    static unsigned callerFlushBits() { return 0; }
#endif
    FlushSubnormals(const FlushSubnormals&) = delete;
    FlushSubnormals& operator=(const FlushSubnormals&) = delete;
};

} // namespace clothtear
