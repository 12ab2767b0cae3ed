// One entry point of each file of entry points, referenced strongly: a static link that looks
// entry points up by name (proc_address.cpp, whose references are weak) brings every one of
// those files along, so the weak references resolve to every entry point there is. A file of
// its own: in proc_address.cpp these names are weak.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

namespace tessel::gl {

extern void (*const kProcAnchors[])();
[[gnu::used]] void (*const kProcAnchors[])() = {
    reinterpret_cast<void (*)()>(&glVertexPointer),
    reinterpret_cast<void (*)()>(&glGenBuffers),
    reinterpret_cast<void (*)()>(&glGetBooleanv),
    reinterpret_cast<void (*)()>(&glLightf),
    reinterpret_cast<void (*)()>(&glMatrixMode),
    reinterpret_cast<void (*)()>(&glPixelStoref),
    reinterpret_cast<void (*)()>(&glCreateShader),
    reinterpret_cast<void (*)()>(&glGetError),
    reinterpret_cast<void (*)()>(&glGenTextures),
    reinterpret_cast<void (*)()>(&glAccum),
    reinterpret_cast<void (*)()>(&glBegin),
    reinterpret_cast<void (*)()>(&glDrawArraysInstanced),
    reinterpret_cast<void (*)()>(&glMap1d),
    reinterpret_cast<void (*)()>(&glFeedbackBuffer),
    reinterpret_cast<void (*)()>(&glRenderMode),
    reinterpret_cast<void (*)()>(&glTexEnvf),
    reinterpret_cast<void (*)()>(&glGenSamplers),
    reinterpret_cast<void (*)()>(&glGenFramebuffers),
    reinterpret_cast<void (*)()>(&glGenQueries),
    reinterpret_cast<void (*)()>(&glWindowPos2f),
    reinterpret_cast<void (*)()>(&glGenFramebuffersEXT),
    reinterpret_cast<void (*)()>(&glGetHandleARB),
};

}  // namespace tessel::gl
