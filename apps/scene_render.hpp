// `tessel render SCENE`: a scene file rendered to PNG, one frame or an animation.
#pragma once

#include <string>

namespace tessel::apps {

struct SceneRenderOptions {
  std::string scene;          // the scene file
  std::string output;         // PNG; with several frames, NAME_0001.png and so on
  int width = 0, height = 0;  // 0: the scene's render.size
  int threads = -1;           // -1: the scene's render.threads
  std::string shading;        // non-empty: every object drawn with this shader
  int first_frame = 0, last_frame = 0;
  bool frames = false;  // --frames given: numbered files
  bool stats = false;   // JSON statistics on stdout
};

// Returns the exit code; errors are printed to stderr.
int render_scene(const SceneRenderOptions& o);

}  // namespace tessel::apps
