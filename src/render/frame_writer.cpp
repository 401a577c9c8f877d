#include "physltl/render/frame_writer.h"

#include "physltl/render/png.h"

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace physltl::render {

struct FrameWriter::Impl {
  struct Job {
    int index;
    std::shared_ptr<const Image> frame;
  };

  std::filesystem::path folder;
  std::size_t max_queued;
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<Job> queue;
  int added = 0;
  int in_progress = 0;
  bool closing = false;
  std::exception_ptr error;
  std::vector<std::thread> workers;

  void work() {
    std::unique_lock lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return closing || !queue.empty(); });
      if (queue.empty()) return;  // closing and nothing left
      Job job = std::move(queue.front());
      queue.pop_front();
      ++in_progress;
      changed.notify_all();  // room in the queue
      lock.unlock();
      std::exception_ptr failure;
      try {
        write_png(*job.frame, frame_path(folder, job.index));
      } catch (...) {
        failure = std::current_exception();
      }
      lock.lock();
      if (failure && !error) error = failure;
      --in_progress;
      changed.notify_all();  // finish() may be waiting
    }
  }
};

FrameWriter::FrameWriter(std::filesystem::path folder, unsigned threads, std::size_t max_queued)
    : impl_(std::make_unique<Impl>()) {
  impl_->folder = std::move(folder);
  impl_->max_queued = std::max<std::size_t>(1, max_queued);
  const unsigned count = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  for (unsigned i = 0; i < count; ++i) impl_->workers.emplace_back([this] { impl_->work(); });
}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard lock(impl_->mutex);
    impl_->closing = true;
  }
  impl_->changed.notify_all();
  for (std::thread& worker : impl_->workers) worker.join();
}

void FrameWriter::add(Image frame) { add(std::make_shared<const Image>(std::move(frame))); }

void FrameWriter::add(std::shared_ptr<const Image> frame) {
  std::unique_lock lock(impl_->mutex);
  impl_->changed.wait(lock, [&] { return impl_->queue.size() < impl_->max_queued; });
  impl_->queue.push_back({impl_->added++, std::move(frame)});
  impl_->changed.notify_all();
}

int FrameWriter::finish() {
  std::unique_lock lock(impl_->mutex);
  impl_->changed.wait(lock, [&] { return impl_->queue.empty() && impl_->in_progress == 0; });
  if (impl_->error) std::rethrow_exception(std::exchange(impl_->error, nullptr));
  return impl_->added;
}

std::filesystem::path FrameWriter::frame_path(const std::filesystem::path& folder, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return folder / name;
}

}  // namespace physltl::render
