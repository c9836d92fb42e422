#include "engine/thread_pool.h"

namespace collide2d::detail {

ThreadPool::ThreadPool(unsigned threads) {
  for (unsigned k = 1; k < threads; ++k) workers_.emplace_back([this, k] { work(k); });
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard lock(mutex_);  // no worker between its check of stopping_ and its wait
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();  // here, while the mutex and condition variables they use still exist
}

// Takes tasks until none is left.
void ThreadPool::drain(unsigned worker) {
  for (std::size_t k = next_.fetch_add(1); k < count_; k = next_.fetch_add(1)) (*task_)(k, worker);
}

void ThreadPool::run(std::size_t count, const Task& task, bool worth_waking) {
  if (!worth_waking || workers_.empty() || count <= 1) {
    for (std::size_t k = 0; k < count; ++k) task(k, 0);
    return;
  }
  {
    const std::lock_guard lock(mutex_);
    task_ = &task;
    count_ = count;
    next_.store(0);
    busy_ = workers_.size();
    ++generation_;
  }
  wake_.notify_all();
  drain(0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return busy_ == 0; });
  task_ = nullptr;
}

void ThreadPool::work(unsigned worker) {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    drain(worker);
    const std::lock_guard lock(mutex_);
    if (--busy_ == 0) done_.notify_one();
  }
}

}  // namespace collide2d::detail
