// The simulation thread of the app's pipeline (sim_thread.h): a job runs on another thread, wait()
// returns only once it has, jobs run one after another in the order started, an exception comes back
// through wait(), and the job's parallel loops use the OpenMP team size of the thread that made it
// (not OpenMP's default for new threads).
#include "sim_thread.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace clothtear::app;

TEST(AppSimThread, RunsTheJobOnAnotherThreadAndWaitReturnsOnceItHas) {
    SimThread sim;
    std::thread::id ran;
    bool finished = false;
    sim.start([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(30)); // wait() must not return before this
        ran = std::this_thread::get_id();
        finished = true;
    });
    sim.wait();
    EXPECT_TRUE(finished);
    EXPECT_NE(ran, std::this_thread::get_id());
    EXPECT_FALSE(sim.busy());
    sim.wait(); // nothing runs: returns at once
}

TEST(AppSimThread, JobsRunInTheOrderStartedOnTheSameThread) {
    SimThread sim;
    std::vector<int> order;
    std::vector<std::thread::id> threads;
    for (int i = 0; i < 50; ++i) {
        sim.start([&, i] {
            order.push_back(i);
            threads.push_back(std::this_thread::get_id());
        });
        sim.wait();
    }
    ASSERT_EQ(order.size(), 50u);
    for (int i = 0; i < 50; ++i) {
        EXPECT_EQ(order[i], i);
        EXPECT_EQ(threads[i], threads[0]) << "one thread for the app's life: its OpenMP team is made once";
    }
}

TEST(AppSimThread, AnExceptionTheJobThrowsIsThrownByWaitAndTheThreadGoesOn) {
    SimThread sim;
    sim.start([] { throw std::runtime_error("step failed"); });
    try {
        sim.wait();
        ADD_FAILURE() << "wait() returned without the job's exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "step failed");
    }
    bool ran = false;
    sim.start([&] { ran = true; });
    EXPECT_NO_THROW(sim.wait()); // thrown once, not again
    EXPECT_TRUE(ran);
}

#ifdef _OPENMP
TEST(AppSimThread, TheJobUsesTheOpenMPTeamSizeOfTheThreadThatMadeIt) {
    const int before = omp_get_max_threads();
    for (int n : {1, 3}) {
        omp_set_num_threads(n); // main() does this for the window on two cores or fewer
        SimThread sim;
        int seen = 0;
        sim.start([&] { seen = omp_get_max_threads(); });
        sim.wait();
        EXPECT_EQ(seen, n);
    }
    omp_set_num_threads(before);
}
#endif
