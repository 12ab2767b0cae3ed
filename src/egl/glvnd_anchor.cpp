// The shared libraries' own object: their entry points come from the static libraries
// linked whole (src/egl/CMakeLists.txt).
namespace tessel::gl {
[[gnu::visibility("hidden")]] int glvnd_anchor = 0;
}  // namespace tessel::gl
