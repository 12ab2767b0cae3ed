// The base of buffers and textures: before a resource changes (or is destroyed), every
// context that still has queued draws runs them, so an upload never races a deferred draw
// that reads the resource (as a vertex buffer, a sampled texture or an attachment).
#pragma once

namespace tessel::gpu {

// Whatever holds deferred work on resources (a Context). Registered while it exists.
class PendingWork {
 public:
  virtual void flush() = 0;
  virtual bool has_pending() const = 0;

 protected:
  PendingWork();
  ~PendingWork();
  PendingWork(const PendingWork&) = delete;
  PendingWork& operator=(const PendingWork&) = delete;
};

class Resource {
 public:
  Resource();
  Resource(const Resource&) = delete;
  Resource& operator=(const Resource&) = delete;
  Resource(Resource&&) noexcept;
  Resource& operator=(Resource&&) noexcept;
  virtual ~Resource();

 protected:
  // Resources call this before changing their contents, and in their destructors (before
  // their members go): queued draws run first.
  void before_write() const;
  // The same for destructors: never throws (a failed flush drops the queued work).
  void flush_before_destruction() const noexcept {
    try {
      before_write();
    } catch (...) {
    }
  }

 private:
  // The number of draws submitted anywhere when this resource was made: while it is
  // unchanged, no draw can refer to the resource yet (a fresh buffer filled right after it is
  // made, a texture built level by level) and writing it needs no flush.
  unsigned long long born_ = 0;
};

// Counts a draw submission (Context::submit): resources made before it may be in use.
void note_draw_submitted();

}  // namespace tessel::gpu
