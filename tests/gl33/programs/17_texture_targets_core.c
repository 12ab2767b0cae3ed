/*
 * Every texture target of GL 3.3 in one core program (GLUT + GLEW), six panels side by side:
 * a 3D texture (a volume sliced by a tilted plane, trilinear), a 2D array of four
 * layers (glTexImage3D, then one layer replaced by glTexSubImage3D), a 1D gradient, a
 * rectangle texture read with texel coordinates, an integer texture (GL_R8UI through a
 * usampler2D and texelFetch, with textureSize), and a buffer texture (GL_RGBA32F texels from
 * a buffer object, texelFetch on a samplerBuffer). Sampler objects set the filters of two of
 * the units instead of the textures' own parameters. Each panel is 96x96 pixels, so that no
 * pixel centre falls exactly on a layer or texel edge (where interpolation rounding decides).
 */
#include "common.h"

static const char* vs =
    "#version 330 core\n"
    "layout (location = 0) in vec2 corner;\n"
    "uniform vec4 rect;\n"
    "out vec2 uv;\n"
    "void main() { uv = corner; gl_Position = vec4(mix(rect.xy, rect.zw, corner), 0.0, 1.0); }\n";
static const char* fs =
    "#version 330 core\n"
    "in vec2 uv;\n"
    "out vec4 color;\n"
    "uniform int panel;\n"
    "uniform sampler3D volume;\n"
    "uniform sampler2DArray layers;\n"
    "uniform sampler1D ramp;\n"
    "uniform sampler2DRect rectangle;\n"
    "uniform usampler2D ids;\n"
    "uniform samplerBuffer palette;\n"
    "void main() {\n"
    "  if (panel == 0) {\n"
    "    color = texture(volume, vec3(uv, uv.x * 0.7 + uv.y * 0.3));\n"
    "  } else if (panel == 1) {\n"
    "    float layer = floor(uv.y * 4.0);\n"
    "    color = texture(layers, vec3(uv.x * 2.0, fract(uv.y * 4.0), layer));\n"
    "  } else if (panel == 2) {\n"
    "    color = texture(ramp, uv.x) * (0.5 + 0.5 * uv.y);\n"
    "  } else if (panel == 3) {\n"
    "    color = texture(rectangle, uv * vec2(textureSize(rectangle)));\n"
    "  } else if (panel == 4) {\n"
    "    ivec2 size = textureSize(ids, 0);\n"
    "    uint id = texelFetch(ids, ivec2(uv * vec2(size)), 0).r;\n"
    "    color = texelFetch(palette, int(id % 4u));\n"
    "  } else {\n"
    "    int n = textureSize(palette);\n"
    "    color = texelFetch(palette, int(uv.x * float(n))) * uv.y + vec4(0.0, 0.0, 0.0, 1.0 - uv.y);\n"
    "  }\n"
    "}\n";

static GLuint prog, vao, tex[6], samplers[2];

static void display(void) {
  int i;
  const char* names[6] = {"volume", "layers", "ramp", "rectangle", "ids", "palette"};
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(prog);
  for (i = 0; i < 6; ++i) glUniform1i(glGetUniformLocation(prog, names[i]), i);
  glBindVertexArray(vao);
  for (i = 0; i < 6; ++i) {
    const float x0 = -0.95f + (float)(i % 3) * 0.65f, y0 = i < 3 ? 0.05f : -0.9f;
    glUniform1i(glGetUniformLocation(prog, "panel"), i);
    glUniform4f(glGetUniformLocation(prog, "rect"), x0, y0, x0 + 0.6f, y0 + 0.8f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  check_gl("display");
  glutSwapBuffers();
}

int main(int argc, char** argv) {
  static const float corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};
  static unsigned char vol[8 * 8 * 8 * 4], layer_data[4][16 * 16 * 4], rect[24 * 10 * 4], ids[16 * 12];
  static const unsigned char ramp[8 * 3] = {0, 0,   0, 255, 0,   0,   255, 128, 0,   255, 255, 0,
                                            0, 255, 0, 0,   255, 255, 0,   0,   255, 255, 255, 255};
  static const float palette[4 * 4] = {0.9f, 0.2f, 0.2f, 1, 0.2f, 0.8f, 0.3f, 1,
                                       0.2f, 0.3f, 0.9f, 1, 0.9f, 0.9f, 0.3f, 1};
  GLuint vbo, pbuf;
  int x, y, z, l;
  open_window(&argc, argv, 3, 3, GLUT_CORE_PROFILE, "texture targets");
  prog = link_program(vs, fs);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, 0);
  glEnableVertexAttribArray(0);
  glGenTextures(6, tex);

  /* 3D: 8x8x8, a colour cube with a lighter shell. */
  for (z = 0; z < 8; ++z)
    for (y = 0; y < 8; ++y)
      for (x = 0; x < 8; ++x) {
        unsigned char* p = &vol[((z * 8 + y) * 8 + x) * 4];
        const int shell = x == 0 || y == 0 || z == 0 || x == 7 || y == 7 || z == 7;
        p[0] = (unsigned char)(x * 36), p[1] = (unsigned char)(y * 36), p[2] = (unsigned char)(z * 36);
        if (shell) p[0] = (unsigned char)(p[0] / 2 + 120), p[1] = (unsigned char)(p[1] / 2 + 120);
        p[3] = 255;
      }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_3D, tex[0]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);

  /* 2D array: four 16x16 layers, stripes of different widths; layer 2 replaced. */
  for (l = 0; l < 4; ++l)
    for (y = 0; y < 16; ++y)
      for (x = 0; x < 16; ++x) {
        unsigned char* p = &layer_data[l][(y * 16 + x) * 4];
        const int on = ((x >> l) & 1) ^ ((y >> 2) & 1);
        p[0] = (unsigned char)(on ? 60 * l + 40 : 20), p[1] = (unsigned char)(on ? 200 - 40 * l : 30);
        p[2] = (unsigned char)(on ? 120 : 60), p[3] = 255;
      }
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex[1]);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, 16, 16, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, layer_data);
  for (y = 0; y < 16 * 16; ++y) layer_data[0][y * 4 + 2] = 250;
  glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 2, 16, 16, 1, GL_RGBA, GL_UNSIGNED_BYTE, layer_data[0]);
  /* Its filters from a sampler object; the texture's own defaults (mipmaps) would be incomplete. */
  glGenSamplers(2, samplers);
  glSamplerParameteri(samplers[0], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(samplers[0], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(samplers[0], GL_TEXTURE_WRAP_S, GL_REPEAT);
  glBindSampler(1, samplers[0]);

  /* 1D: an 8-texel rainbow, linear through a second sampler object. */
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_1D, tex[2]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glSamplerParameteri(samplers[1], GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(samplers[1], GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(samplers[1], GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glBindSampler(2, samplers[1]);

  /* Rectangle: 24x10 texels, a diagonal pattern, nearest. */
  for (y = 0; y < 10; ++y)
    for (x = 0; x < 24; ++x) {
      unsigned char* p = &rect[(y * 24 + x) * 4];
      const int on = ((x + y) / 3) % 2;
      p[0] = (unsigned char)(on ? 240 : 40), p[1] = (unsigned char)(on ? 160 : 40);
      p[2] = (unsigned char)(x * 10), p[3] = 255;
    }
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_RECTANGLE, tex[3]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_RECTANGLE, 0, GL_RGBA8, 24, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE, rect);
  glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  /* Integer ids: 16x12 R8UI, read by texelFetch only. */
  for (y = 0; y < 12; ++y)
    for (x = 0; x < 16; ++x) ids[y * 16 + x] = (unsigned char)((x / 4 + y / 3) % 4 + 4 * (x % 2));
  glActiveTexture(GL_TEXTURE4);
  glBindTexture(GL_TEXTURE_2D, tex[4]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, 16, 12, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, ids);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  /* A buffer texture: four RGBA32F colours. */
  glGenBuffers(1, &pbuf);
  glBindBuffer(GL_TEXTURE_BUFFER, pbuf);
  glBufferData(GL_TEXTURE_BUFFER, sizeof palette, palette, GL_STATIC_DRAW);
  glActiveTexture(GL_TEXTURE5);
  glBindTexture(GL_TEXTURE_BUFFER, tex[5]);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, pbuf);
  glActiveTexture(GL_TEXTURE0);
  check_gl("setup");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
