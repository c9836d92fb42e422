// A small pool of std::thread workers for the World's per-frame work: run(count, task) calls
// task(k, worker) for every k in [0, count), spread over the workers and the calling thread, and
// returns when all calls are done. `worker` names the thread in [0, threads()), the calling thread
// 0, so that a task may use scratch space of its thread's own. Tasks are taken in order from an
// atomic counter, so a slow one does not hold the others back. The workers sleep on a condition
// variable between runs. Standard threads rather than oneTBB: the World needs one parallel loop per
// phase and nothing of TBB's scheduler, and the library keeps linking only Eigen (and the standard
// library's threads). std::thread rather than std::jthread, which the C++ library of Emscripten 3.1
// lacks.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace collide2d::detail {

class ThreadPool {
 public:
  // threads >= 1 counts the calling thread: threads - 1 workers are started.
  explicit ThreadPool(unsigned threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }
  using Task = std::function<void(std::size_t k, unsigned worker)>;
  // worth_waking false runs every task on the calling thread: for work smaller than the cost of
  // waking the workers (and of fetching back the cache lines they took).
  void run(std::size_t count, const Task& task, bool worth_waking = true);

 private:
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const Task* task_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_{0};
  std::size_t busy_ = 0;          // workers still in the current run
  std::uint64_t generation_ = 0;  // one per run, so that a worker joins each run once
  bool stopping_ = false;         // set under the mutex when the pool closes

  void work(unsigned worker);
  void drain(unsigned worker);
};

}  // namespace collide2d::detail
