#include "tessel/gpu/resource.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <vector>

namespace tessel::gpu {
namespace {
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::vector<PendingWork*>& registry() {
  static std::vector<PendingWork*> r;
  return r;
}
std::atomic<unsigned long long> g_submitted{0};
}  // namespace

void note_draw_submitted() { g_submitted.fetch_add(1, std::memory_order_acq_rel); }

Resource::Resource() : born_(g_submitted.load(std::memory_order_acquire)) {}

PendingWork::PendingWork() {
  std::lock_guard lock(registry_mutex());
  registry().push_back(this);
}

PendingWork::~PendingWork() {
  std::lock_guard lock(registry_mutex());
  auto& r = registry();
  r.erase(std::remove(r.begin(), r.end(), this), r.end());
}

Resource::Resource(Resource&&) noexcept : born_(g_submitted.load(std::memory_order_acquire)) {
  before_write();
}

Resource& Resource::operator=(Resource&&) noexcept {
  before_write();
  return *this;
}

Resource::~Resource() {
  try {
    before_write();
  } catch (...) {
    // A destructor cannot report; the queued work was dropped with the failed flush.
  }
}

void Resource::before_write() const {
  // No draw was submitted since this resource was made: none can read it.
  if (g_submitted.load(std::memory_order_acquire) == born_) return;
  std::vector<PendingWork*> busy;
  {
    std::lock_guard lock(registry_mutex());
    for (PendingWork* p : registry())
      if (p->has_pending()) busy.push_back(p);
  }
  for (PendingWork* p : busy) p->flush();
}

}  // namespace tessel::gpu
