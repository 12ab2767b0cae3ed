// Vertex and index buffers, and the layout that says how vertex attributes are read from them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "tessel/gpu/format.hpp"
#include "tessel/gpu/resource.hpp"

namespace tessel::gpu {

inline constexpr int kMaxVertexAttribs = 16;
inline constexpr int kMaxVertexBindings = 16;

// Bytes, as glBufferData keeps them.
class Buffer : public Resource {
 public:
  Buffer() = default;
  explicit Buffer(size_t bytes) : data_(bytes) {}
  Buffer(const void* data, size_t bytes) { assign(data, bytes); }
  template <class T>
  explicit Buffer(std::span<const T> items) {
    assign(items.data(), items.size_bytes());
  }
  template <class T>
  explicit Buffer(const std::vector<T>& items) {
    assign(items.data(), items.size() * sizeof(T));
  }
  // Queued draws that read this buffer run before its memory goes.
  ~Buffer() override { flush_before_destruction(); }

  void assign(const void* data, size_t bytes) {
    before_write();
    max_cache_.clear();
    data_.resize(bytes);
    if (bytes) std::memcpy(data_.data(), data, bytes);
  }
  // Throws Error when offset + bytes is past the end.
  void update(size_t offset, const void* data, size_t bytes);
  // The bytes, for the caller to change in place (glMapBuffer): queued draws that read the
  // buffer run first, and what was derived from the contents is forgotten.
  std::byte* writable() {
    before_write();
    max_cache_.clear();
    return data_.data();
  }
  size_t size() const { return data_.size(); }
  const std::byte* data() const { return data_.data(); }
  // The largest of `count` 32-bit values from byte `offset` (4-aligned, in range): what a
  // draw must check its indices against. Remembered per range until the buffer changes, as
  // GL drivers do for index buffers drawn again every frame (Mesa's vbo minmax cache).
  uint32_t max_u32(size_t offset, size_t count) const;

 private:
  std::vector<std::byte> data_;
  struct RangeMax {
    size_t offset, count;
    uint32_t max;
  };
  mutable std::vector<RangeMax> max_cache_;
};

// The type of one attribute component in memory.
enum class AttribType : uint8_t { F32, F16, I8, U8, I16, U16, I32, U32 };

struct VertexAttrib {
  bool enabled = false;
  int binding = 0;     // which VertexBinding supplies it
  int components = 4;  // 1..4; missing components read as (0, 0, 0, 1)
  AttribType type = AttribType::F32;
  bool normalized = false;  // integer types: map to [0,1] / [-1,1] (GL 4.6 §2.3.5.1)
  bool integer = false;     // glVertexAttribIPointer: the shader reads the integer bits
  uint32_t offset = 0;      // relative to the binding's offset
};

struct VertexBinding {
  const Buffer* buffer = nullptr;
  size_t offset = 0;
  uint32_t stride = 0;   // bytes between consecutive elements; 0 = tightly packed
  uint32_t divisor = 0;  // 0: per vertex; n: advances once every n instances
};

// Where every attribute location reads from. Locations that are not enabled read as the
// constant `current` value (glVertexAttrib4f).
struct VertexLayout {
  std::array<VertexAttrib, kMaxVertexAttribs> attribs{};
  std::array<VertexBinding, kMaxVertexBindings> bindings{};
  std::array<std::array<float, 4>, kMaxVertexAttribs> current{};

  VertexLayout() {
    for (auto& c : current) c = {0.0f, 0.0f, 0.0f, 1.0f};
  }
  // Convenience: location reads `components` values of `type` from `buffer`.
  VertexLayout& attrib(int location, const Buffer& buffer, int components, AttribType type, uint32_t stride,
                       uint32_t offset, bool normalized = false, uint32_t divisor = 0) {
    auto& a = attribs.at(location);
    a = {true, location, components, type, normalized, false, offset};
    bindings.at(location) = {&buffer, 0, stride, divisor};
    return *this;
  }
};

size_t attrib_type_size(AttribType t);

}  // namespace tessel::gpu
