#include "compile_queue.hpp"

#include "jit.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace tessel::glsl {

// The queue is made once and never destroyed: at exit a handler stops it (drops the jobs not
// started, waits for the one running). That handler must run before LLVM's static objects
// are destroyed, and exit runs handlers and static destructors in the reverse order of their
// registration; LLVM makes many of its statics lazily, during a process's first compiles,
// so a compile is made here first (jit_warm_up), and the handler registered after it.
// (Registered before, an exit during a compile crashed in LLVM's legalizer, whose type
// tables had been destroyed under it.)
static void stop_at_exit() { CompileQueue::instance().stop(); }

CompileQueue& CompileQueue::instance() {
  static CompileQueue* const q = [] {
    jit_warm_up();
    auto* made = new CompileQueue;
    std::atexit(stop_at_exit);
    return made;
  }();
  return *q;
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
    // Statics LLVM made in this compile are destroyed at exit before handlers registered
    // earlier run: register the handler again (stop() runs once).
    std::atexit(stop_at_exit);
    lock.lock();
  }
}

void CompileQueue::stop() {
  std::deque<Job> dropped;
  {
    std::lock_guard lock(m_);
    if (stop_) return;
    stop_ = true;
    dropped.swap(jobs_);
    cv_.notify_one();
  }
  if (thread_.joinable() && thread_.get_id() != std::this_thread::get_id()) thread_.join();
  for (Job& j : dropped) j.fn(false);
}

CompileQueue::~CompileQueue() { stop(); }  // (not reached: the queue lives to the end)

}  // namespace tessel::glsl
