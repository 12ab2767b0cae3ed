// The background tier's compiler thread: native-code compiles queued by Program::link run here,
// one at a time, while the program already draws on the interpreter (same bits). A draw that
// binds a program whose compile is still queued moves it to the front.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace tessel::glsl {

class CompileQueue {
 public:
  // The process's queue; its thread starts with the first job. At exit the queue drops the
  // jobs not started and waits for the one running (LLVM's state must outlive it).
  static CompileQueue& instance();

  // Queues `job` under `key` (any address that names it, for promote()). The queue calls
  // job(true) on its thread, or job(false) when it drops the job at exit, so that whoever
  // waits for it is told.
  void submit(const void* key, std::function<void(bool run)> job);
  // Moves the job of `key` to the front if it is still waiting.
  void promote(const void* key);
  // Tests only: while paused no new job starts (the one running finishes).
  void pause(bool paused);
  // Drops the jobs not started (telling their owners) and waits for the one running; later
  // submissions are dropped at once. Run at exit.
  void stop();

  ~CompileQueue();

 private:
  CompileQueue() = default;
  void run();

  struct Job {
    const void* key;
    std::function<void(bool)> fn;
  };
  std::mutex m_;
  std::condition_variable cv_;
  std::deque<Job> jobs_;
  std::thread thread_;
  bool stop_ = false;
  bool paused_ = false;
};

}  // namespace tessel::glsl
