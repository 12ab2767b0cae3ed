// The worker threads of a Context: worker 0 is the calling thread, the others wait for a
// job, run it with their index and report back; an exception in any worker is rethrown by
// run() once all have finished.
#include "frame.hpp"

namespace tessel::gpu {

Context::WorkerPool::WorkerPool(int n) : size_(n) {
  for (int i = 1; i < n; ++i) threads_.emplace_back([this, i] { loop(i); });
}

Context::WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(m_);
    stop_ = true;
    ++generation_;
  }
  cv_.notify_all();
  for (auto& t : threads_) t.join();
}

void Context::WorkerPool::run(const std::function<void(int)>& fn) {
  error_ = nullptr;
  if (size_ == 1) {
    fn(0);
    return;
  }
  {
    std::lock_guard lock(m_);
    job_ = &fn;
    running_ = size_ - 1;
    ++generation_;
  }
  cv_.notify_all();
  std::exception_ptr mine;
  try {
    fn(0);
  } catch (...) {
    mine = std::current_exception();
  }
  std::unique_lock lock(m_);
  done_.wait(lock, [&] { return running_ == 0; });
  job_ = nullptr;
  if (mine) std::rethrow_exception(mine);
  if (error_) std::rethrow_exception(error_);
}

void Context::WorkerPool::loop(int index) {
  uint64_t seen = 0;
  for (;;) {
    const std::function<void(int)>* job;
    {
      std::unique_lock lock(m_);
      cv_.wait(lock, [&] { return generation_ != seen; });
      seen = generation_;
      if (stop_) return;
      job = job_;
    }
    std::exception_ptr e;
    try {
      (*job)(index);
    } catch (...) {
      e = std::current_exception();
    }
    {
      std::lock_guard lock(m_);
      if (e && !error_) error_ = e;
      if (--running_ == 0) done_.notify_one();
    }
  }
}

}  // namespace tessel::gpu
