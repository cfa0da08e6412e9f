// The software raster threads yield to the simulation (raster_priority.h): threads named as
// llvmpipe names its own get the nice value asked, every other thread keeps its own.
#include "raster_priority.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <pthread.h>
#include <string>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>

using namespace clothtear::app;

namespace {

// A thread with a name that waits until the test lets it go; its nice value read by its kernel id.
class NamedThread {
public:
    explicit NamedThread(const char* name) {
        thread_ = std::thread([this, name] {
            pthread_setname_np(pthread_self(), name);
            std::unique_lock lock(mutex_);
            tid_ = pid_t(syscall(SYS_gettid));
            ready_.notify_all();
            ready_.wait(lock, [this] { return done_; });
        });
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [this] { return tid_ != 0; });
    }
    ~NamedThread() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
        }
        ready_.notify_all();
        thread_.join();
    }
    int niceness() const {
        errno = 0;
        return getpriority(PRIO_PROCESS, id_t(tid_));
    }

private:
    std::mutex mutex_;
    std::condition_variable ready_;
    pid_t tid_ = 0;
    bool done_ = false;
    std::thread thread_;
};

int ownNiceness() { return getpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid))); }

} // namespace

TEST(RasterPriority, OnlyTheRasterThreadsGetTheNiceValue) {
    NamedThread raster0("llvmpipe-0"), raster1("llvmpipe-1"), other("worker"), lookalike("xllvmpipe-0");
    const int before = ownNiceness();
    ASSERT_EQ(raster0.niceness(), before);
    // 0 leaves them alone.
    RasterYield none = yieldSoftwareRaster(0);
    EXPECT_EQ(none.threads, 0);
    EXPECT_EQ(raster0.niceness(), before);
    // A nice value above the process's own (an unprivileged thread may only raise it).
    const int asked = std::min(19, before + 7);
    ASSERT_GT(asked, before) << "the test process already runs at nice " << before;
    RasterYield done = yieldSoftwareRaster(asked);
    EXPECT_TRUE(done.error.empty()) << done.error;
    EXPECT_EQ(done.threads, 2);
    EXPECT_EQ(done.niceness, asked);
    EXPECT_EQ(raster0.niceness(), asked);
    EXPECT_EQ(raster1.niceness(), asked);
    EXPECT_EQ(other.niceness(), before);
    EXPECT_EQ(lookalike.niceness(), before);
    EXPECT_EQ(ownNiceness(), before);
}

TEST(RasterPriority, TheEnvironmentPicksTheValueAndABadOneSaysSo) {
    const char* saved = std::getenv("CLOTHTEAR_RASTER_NICE");
    const std::string keep = saved ? saved : "";
    unsetenv("CLOTHTEAR_RASTER_NICE");
    RasterNiceness n = rasterNicenessFromEnv(10);
    EXPECT_EQ(n.value, 10);
    EXPECT_TRUE(n.error.empty());
    setenv("CLOTHTEAR_RASTER_NICE", "0", 1);
    n = rasterNicenessFromEnv(10);
    EXPECT_EQ(n.value, 0);
    EXPECT_TRUE(n.error.empty());
    setenv("CLOTHTEAR_RASTER_NICE", "19", 1);
    EXPECT_EQ(rasterNicenessFromEnv(10).value, 19);
    for (const char* bad : {"20", "-1", "5x", "", "high", "99999999999999999999"}) {
        setenv("CLOTHTEAR_RASTER_NICE", bad, 1);
        n = rasterNicenessFromEnv(10);
        EXPECT_EQ(n.value, 10) << bad;
        const std::string said = std::string("CLOTHTEAR_RASTER_NICE=") + bad + " is not";
        EXPECT_NE(n.error.find(said), std::string::npos) << n.error;
    }
    if (saved) setenv("CLOTHTEAR_RASTER_NICE", keep.c_str(), 1);
    else unsetenv("CLOTHTEAR_RASTER_NICE");
}
