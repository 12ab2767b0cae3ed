// The base of buffers and textures: lets a context finish the draws that still read a
// resource before the resource is changed, so an upload never races a deferred draw.
#pragma once

namespace tessel::gpu {

class Context;

class Resource {
 public:
  Resource() = default;
  Resource(const Resource&) = delete;
  Resource& operator=(const Resource&) = delete;
  virtual ~Resource();

  // Called by a context when it queues a draw that uses this resource.
  void mark_used_by(Context* ctx) const { pending_ = ctx; }
  // Called by a context when its queued draws have run.
  void release_from(const Context* ctx) const {
    if (pending_ == ctx) pending_ = nullptr;
  }

 protected:
  // Resources call this before changing their contents.
  void before_write() const;

 private:
  mutable Context* pending_ = nullptr;
};

}  // namespace tessel::gpu
