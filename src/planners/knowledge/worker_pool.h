#pragma once
// Runs a batch of independent tasks on a fixed set of threads and waits for all of them. The calling
// thread is worker 0, so a pool of one thread starts none and runs everything in place.

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace physltl::planners::knowledge {

class WorkerPool {
 public:
  // job(worker, task): `worker` in [0, threads) names the thread, so each can keep its own scratch state.
  using Job = std::function<void(int worker, int task)>;

  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }

  // Calls job for every task in [0, tasks) and returns when all are done. Which worker runs which task
  // depends on timing; an exception thrown by a task is rethrown here, after the batch.
  void run(int tasks, const Job& job);

 private:
  void help(int worker);
  void work(int worker);
  void close();  // stops and joins the helpers

  std::mutex mutex_;
  std::condition_variable batch_ready_;
  std::condition_variable batch_done_;
  const Job* job_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> next_task_{0};
  int helpers_busy_ = 0;
  long long batch_ = 0;  // how many batches were started; helpers wait for it to change
  bool closing_ = false;
  std::exception_ptr failure_;
  std::vector<std::jthread> helpers_;
};

}  // namespace physltl::planners::knowledge
