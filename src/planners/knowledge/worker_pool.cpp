#include "worker_pool.h"

#include <algorithm>

namespace physltl::planners::knowledge {

WorkerPool::WorkerPool(int threads) {
  try {
    for (int w = 1; w < std::max(threads, 1); ++w) helpers_.emplace_back([this, w] { help(w); });
  } catch (...) {
    close();  // the helpers already started wait for a batch; they must be told to leave before joining
    throw;
  }
}

WorkerPool::~WorkerPool() { close(); }

void WorkerPool::close() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  batch_ready_.notify_all();
  helpers_.clear();  // joins
}

void WorkerPool::run(int tasks, const Job& job) {
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    tasks_ = tasks;
    next_task_.store(0);
    helpers_busy_ = static_cast<int>(helpers_.size());
    failure_ = nullptr;
    ++batch_;
  }
  batch_ready_.notify_all();
  work(0);
  std::unique_lock lock(mutex_);
  batch_done_.wait(lock, [this] { return helpers_busy_ == 0; });
  job_ = nullptr;
  if (failure_) std::rethrow_exception(failure_);
}

void WorkerPool::help(int worker) {
  long long seen = 0;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      batch_ready_.wait(lock, [&] { return closing_ || batch_ != seen; });
      if (closing_) return;
      seen = batch_;
    }
    work(worker);
    std::lock_guard lock(mutex_);
    if (--helpers_busy_ == 0) batch_done_.notify_one();
  }
}

void WorkerPool::work(int worker) {
  for (int task = next_task_.fetch_add(1); task < tasks_; task = next_task_.fetch_add(1)) {
    try {
      (*job_)(worker, task);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
    }
  }
}

}  // namespace physltl::planners::knowledge
