#include "compile_queue.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace tessel::glsl {

CompileQueue& CompileQueue::instance() {
  static CompileQueue q;
  return q;
}

void CompileQueue::submit(const void* key, std::function<void(bool)> job) {
  std::unique_lock lock(m_);
  if (stop_) {  // exiting: the program stays on the interpreter
    lock.unlock();
    job(false);
    return;
  }
  jobs_.push_back({key, std::move(job)});
  if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  cv_.notify_one();
}

void CompileQueue::promote(const void* key) {
  std::lock_guard lock(m_);
  auto it = std::find_if(jobs_.begin(), jobs_.end(), [&](const Job& j) { return j.key == key; });
  if (it == jobs_.begin() || it == jobs_.end()) return;
  Job j = std::move(*it);
  jobs_.erase(it);
  jobs_.push_front(std::move(j));
}

void CompileQueue::pause(bool paused) {
  std::lock_guard lock(m_);
  paused_ = paused;
  cv_.notify_one();
}

void CompileQueue::run() {
  std::unique_lock lock(m_);
  for (;;) {
    cv_.wait(lock, [&] { return stop_ || (!paused_ && !jobs_.empty()); });
    if (stop_) return;
    Job j = std::move(jobs_.front());
    jobs_.pop_front();
    lock.unlock();
    j.fn(true);
    lock.lock();
  }
}

void CompileQueue::stop() {
  std::deque<Job> dropped;
  {
    std::lock_guard lock(m_);
    stop_ = true;
    dropped.swap(jobs_);
    cv_.notify_one();
  }
  if (thread_.joinable() && thread_.get_id() != std::this_thread::get_id()) thread_.join();
  for (Job& j : dropped) j.fn(false);
}

CompileQueue::~CompileQueue() { stop(); }

}  // namespace tessel::glsl
