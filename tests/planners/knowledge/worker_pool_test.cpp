#include "worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <thread>
#include <set>
#include <stdexcept>
#include <vector>

namespace physltl::planning {
namespace {

using namespace physltl::planners::knowledge;

TEST(WorkerPool, RunsEveryTaskOnceInEveryBatch) {
  WorkerPool pool(3);
  ASSERT_EQ(pool.threads(), 3);
  for (int batch = 0; batch < 200; ++batch) {
    std::vector<std::atomic<int>> runs(17);
    pool.run(17, [&](int worker, int task) {
      ASSERT_GE(worker, 0);
      ASSERT_LT(worker, 3);
      runs[static_cast<size_t>(task)].fetch_add(1);
    });
    for (const auto& r : runs) ASSERT_EQ(r.load(), 1) << "batch " << batch;
  }
}

TEST(WorkerPool, TheHelpersShareTheWork) {
  WorkerPool pool(2);
  std::mutex mutex;
  std::set<int> workers;
  // Tasks that wait for each other can only finish if two threads run them at once.
  std::atomic<int> started{0};
  pool.run(2, [&](int worker, int) {
    started.fetch_add(1);
    while (started.load() < 2) std::this_thread::yield();
    std::lock_guard lock(mutex);
    workers.insert(worker);
  });
  EXPECT_EQ(workers, (std::set<int>{0, 1}));
}

TEST(WorkerPool, OneThreadRunsEverythingInTheCaller) {
  WorkerPool pool(1);
  const auto caller = std::this_thread::get_id();
  int runs = 0;
  pool.run(5, [&](int worker, int) {
    EXPECT_EQ(worker, 0);
    EXPECT_EQ(std::this_thread::get_id(), caller);
    ++runs;
  });
  EXPECT_EQ(runs, 5);
}

TEST(WorkerPool, ATaskThatThrowsFailsTheBatchButNotThePool) {
  WorkerPool pool(2);
  std::atomic<int> runs{0};
  EXPECT_THROW(pool.run(8, [&](int, int task) {
    runs.fetch_add(1);
    if (task == 3) throw std::runtime_error("task 3");
  }),
               std::runtime_error);
  EXPECT_EQ(runs.load(), 8);  // the other tasks still ran
  int after = 0;
  pool.run(4, [&](int, int) { std::atomic_ref(after).fetch_add(1); });
  EXPECT_EQ(after, 4);
}

}  // namespace
}  // namespace physltl::planning
