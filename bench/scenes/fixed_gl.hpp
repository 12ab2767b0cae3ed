// The fixed-100k scene (../shared/scenes/README.md) as OpenGL 1.x calls: the spheres-100k
// grid drawn with vertex arrays and fixed-function lighting, Gouraud shaded. Both renderers
// include this header: `tessel bench` against Tessel's <GL/gl.h> (include/compat, linked to
// tessel_gl) and the llvmpipe peer against the system's, so both issue the same calls.
#pragma once

#include <GL/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "scenes.hpp"

namespace tessel::scenes {

// State that does not change from frame to frame.
inline void fixed_setup(const Scene& s) {
  glViewport(0, 0, s.width, s.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f}, black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_AMBIENT, white);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  const GLfloat spec[4] = {kSpecular, kSpecular, kSpecular, 1.0f}, emission[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, emission);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, kShininess);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  const GLsizei stride = Mesh::kStride * sizeof(float);
  glVertexPointer(3, GL_FLOAT, stride, s.mesh.vertices.data());
  glNormalPointer(GL_FLOAT, stride, s.mesh.vertices.data() + 3);
}

// One frame: clear, camera, the light at its world position (set after the view matrix, so
// it is transformed into eye space), then each sphere with its material.
inline void fixed_frame(const Scene& s) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(glm::value_ptr(s.projection));
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(glm::value_ptr(s.view));
  const GLfloat light[4] = {s.light.x, s.light.y, s.light.z, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  for (const Draw& d : s.draws) {
    glPushMatrix();
    glTranslatef(d.offset.x, d.offset.y, d.offset.z);
    const GLfloat ambient[4] = {kAmbient * d.albedo.x, kAmbient * d.albedo.y, kAmbient * d.albedo.z, 1.0f};
    const GLfloat diffuse[4] = {kDiffuse * d.albedo.x, kDiffuse * d.albedo.y, kDiffuse * d.albedo.z, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glDrawElements(GL_TRIANGLES, GLsizei(d.index_count), GL_UNSIGNED_INT,
                   s.mesh.indices.data() + d.first_index);
    glPopMatrix();
  }
}

}  // namespace tessel::scenes
