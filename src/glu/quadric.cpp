// GLU 1.3 quadrics (section 6): spheres, cylinders, disks and partial disks drawn with GL 1.1
// immediate mode (glBegin/glEnd, glNormal3f, glTexCoord2f, glVertex3f).
//
// The specification fixes the shapes, the parameterisation and the texture coordinates; the
// primitive types, the vertex order and the single-precision arithmetic below follow what the
// reference GLU (the one Mesa ships) sends to GL, so that images agree with it pixel for pixel:
//  - angles around z are measured from +y towards +x (x = r sin a, y = r cos a);
//  - a sphere runs from +z (stack 0) to -z, a cylinder from z = 0 to z = height, a disk from
//    the outer radius inwards;
//  - texture s runs 1 -> 0 around a sphere or cylinder (as the reference GLU does), t along z
//    (spheres: t = 1 at +z); disks map the outer circle onto the unit square.

#include <GL/gl.h>
#include <GL/glu.h>

#include <cmath>
#include <new>
#include <vector>

struct GLUquadric {
  GLenum drawStyle = GLU_FILL;
  GLenum orientation = GLU_OUTSIDE;
  GLenum normals = GLU_SMOOTH;
  bool texture = false;
  void(GLAPIENTRY* errorCallback)(GLenum) = nullptr;
};

namespace {

constexpr double kPi = 3.14159265358979323846;
// Tessellations are capped like the reference GLU's (its tables hold 240 entries).
constexpr int kMaxDivisions = 239;

void quadricError(GLUquadric* q, GLenum error) {
  if (q->errorCallback) q->errorCallback(error);
}

float fsin(float a) { return static_cast<float>(std::sin(static_cast<double>(a))); }
float fcos(float a) { return static_cast<float>(std::cos(static_cast<double>(a))); }

// sin and cos of n+1 angles a(i) = angle(i), with the last entry equal to the first when the
// circle closes.
struct Circle {
  std::vector<float> s, c;
};

template <class F>
Circle circle(int n, F angle, bool closed) {
  Circle t;
  t.s.resize(n + 1);
  t.c.resize(n + 1);
  for (int i = 0; i <= n; i++) {
    const float a = static_cast<float>(angle(i));
    t.s[i] = fsin(a);
    t.c[i] = fcos(a);
  }
  if (closed) {
    t.s[n] = t.s[0];
    t.c[n] = t.c[0];
  }
  return t;
}

}  // namespace

extern "C" {

GLUquadric* GLAPIENTRY gluNewQuadric(void) { return new (std::nothrow) GLUquadric(); }

void GLAPIENTRY gluDeleteQuadric(GLUquadric* q) { delete q; }

void GLAPIENTRY gluQuadricCallback(GLUquadric* q, GLenum which, _GLUfuncptr fn) {
  if (which != GLU_ERROR) {
    quadricError(q, GLU_INVALID_ENUM);
    return;
  }
  q->errorCallback = reinterpret_cast<void(GLAPIENTRY*)(GLenum)>(fn);
}

void GLAPIENTRY gluQuadricNormals(GLUquadric* q, GLenum normals) {
  if (normals != GLU_SMOOTH && normals != GLU_FLAT && normals != GLU_NONE) {
    quadricError(q, GLU_INVALID_ENUM);
    return;
  }
  q->normals = normals;
}

void GLAPIENTRY gluQuadricTexture(GLUquadric* q, GLboolean texture) { q->texture = texture != GL_FALSE; }

void GLAPIENTRY gluQuadricOrientation(GLUquadric* q, GLenum orientation) {
  if (orientation != GLU_OUTSIDE && orientation != GLU_INSIDE) {
    quadricError(q, GLU_INVALID_ENUM);
    return;
  }
  q->orientation = orientation;
}

void GLAPIENTRY gluQuadricDrawStyle(GLUquadric* q, GLenum style) {
  if (style != GLU_FILL && style != GLU_LINE && style != GLU_SILHOUETTE && style != GLU_POINT) {
    quadricError(q, GLU_INVALID_ENUM);
    return;
  }
  q->drawStyle = style;
}

// ---------------------------------------------------------------------------------------------
// Section 6.6: a cylinder (or cone) around z from z = 0 (baseRadius) to z = height (topRadius),
// in `slices` subdivisions around z and `stacks` along it.
void GLAPIENTRY gluCylinder(GLUquadric* q, GLdouble baseRadius, GLdouble topRadius, GLdouble height,
                            GLint slices, GLint stacks) {
  if (slices > kMaxDivisions) slices = kMaxDivisions;
  if (slices < 2 || stacks < 1 || baseRadius < 0.0 || topRadius < 0.0 || height < 0.0) {
    quadricError(q, GLU_INVALID_VALUE);
    return;
  }
  const float dr = static_cast<float>(baseRadius - topRadius);
  const float len = static_cast<float>(std::sqrt(dr * dr + height * height));
  if (len == 0.0f) {
    quadricError(q, GLU_INVALID_VALUE);
    return;
  }
  const bool outside = q->orientation == GLU_OUTSIDE;
  // The side's normal leans along z by the slope of the side.
  const float nz = dr / len;
  const float nxy = static_cast<float>(height / len) * (outside ? 1.0f : -1.0f);

  const Circle pos = circle(
      slices, [&](int i) { return 2 * kPi * i / slices; }, true);
  // Smooth normals point the way of the vertices; flat normals the way of the middle of each
  // face (half a slice back), given with the face's last edge. The products are rounded once,
  // from the double-precision sine and cosine of the single-precision angle.
  std::vector<float> ns(slices + 1), nc(slices + 1), fs(slices + 1), fc(slices + 1);
  for (int i = 0; i < slices; i++) {
    const double a = static_cast<float>(2 * kPi * i / slices);
    const double af = static_cast<float>(2 * kPi * (i - 0.5) / slices);
    ns[i] = static_cast<float>(nxy * std::sin(a));
    nc[i] = static_cast<float>(nxy * std::cos(a));
    fs[i] = static_cast<float>(nxy * std::sin(af));
    fc[i] = static_cast<float>(nxy * std::cos(af));
  }
  ns[slices] = ns[0];
  nc[slices] = nc[0];
  fs[slices] = fs[0];
  fc[slices] = fc[0];

  auto z = [&](int j) { return static_cast<float>(j * height / stacks); };
  auto radius = [&](int j) { return static_cast<float>(baseRadius - dr * (static_cast<float>(j) / stacks)); };
  auto s = [&](int i) { return 1 - static_cast<float>(i) / slices; };
  auto t = [&](int j) { return static_cast<float>(j) / stacks; };
  auto vertex = [&](int i, int j) {
    if (q->texture) glTexCoord2f(s(i), t(j));
    const float r = radius(j);
    glVertex3f(r * pos.s[i], r * pos.c[i], z(j));
  };
  auto normal = [&](int i) {
    if (q->normals == GLU_FLAT)
      glNormal3f(fs[i], fc[i], nz);
    else if (q->normals == GLU_SMOOTH)
      glNormal3f(ns[i], nc[i], nz);
  };

  switch (q->drawStyle) {
    case GLU_FILL:
      // One quad strip per stack, each slice's edge bottom then top (top then bottom inside).
      for (int j = 0; j < stacks; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= slices; i++) {
          normal(i);
          if (outside) {
            vertex(i, j);
            vertex(i, j + 1);
          } else {
            vertex(i, j + 1);
            vertex(i, j);
          }
        }
        glEnd();
      }
      break;
    case GLU_POINT:
      // Points and the lines along z get smooth normals for GLU_FLAT too. (The reference GLU
      // sends values from uninitialised memory there; nothing can agree with that.)
      glBegin(GL_POINTS);
      for (int i = 0; i < slices; i++) {
        if (q->normals != GLU_NONE) glNormal3f(ns[i], nc[i], nz);
        for (int j = 0; j <= stacks; j++) vertex(i, j);
      }
      glEnd();
      break;
    case GLU_LINE:
      // The rings between the ends, then everything the silhouette draws.
      for (int j = 1; j < stacks; j++) {
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; i++) {
          normal(i);
          vertex(i, j);
        }
        glEnd();
      }
      [[fallthrough]];
    case GLU_SILHOUETTE:
      // The two end rings, then one line along z per slice edge (normals without a z part).
      for (int j = 0; j <= stacks; j += stacks) {
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; i++) {
          normal(i);
          vertex(i, j);
        }
        glEnd();
      }
      for (int i = 0; i < slices; i++) {
        if (q->normals != GLU_NONE) glNormal3f(ns[i], nc[i], 0.0f);
        glBegin(GL_LINE_STRIP);
        for (int j = 0; j <= stacks; j++) vertex(i, j);
        glEnd();
      }
      break;
    default: break;
  }
}

// ---------------------------------------------------------------------------------------------
// Section 6.8: a partial disk in z = 0 between innerRadius and outerRadius, from startAngle
// over sweepAngle degrees, measured clockwise from +y (towards +x), in `slices` subdivisions
// around z and `loops` rings (outermost first).
void GLAPIENTRY gluPartialDisk(GLUquadric* q, GLdouble innerRadius, GLdouble outerRadius, GLint slices,
                               GLint loops, GLdouble startAngle, GLdouble sweepAngle) {
  if (slices > kMaxDivisions) slices = kMaxDivisions;
  if (slices < 2 || loops < 1 || outerRadius <= 0.0 || innerRadius < 0.0 || innerRadius > outerRadius) {
    quadricError(q, GLU_INVALID_VALUE);
    return;
  }
  if (sweepAngle < -360.0 || sweepAngle > 360.0) sweepAngle = 360.0;
  if (sweepAngle < 0) {
    startAngle += sweepAngle;
    sweepAngle = -sweepAngle;
  }
  const bool full = sweepAngle == 360.0;
  // A partial disk has one more radial edge than it has slices.
  const int edges = full ? slices : slices + 1;
  const float dr = static_cast<float>(outerRadius - innerRadius);
  const float start = static_cast<float>(startAngle / 180.0 * kPi);
  const double step = kPi * sweepAngle / 180.0;
  const Circle a = circle(
      slices, [&](int i) { return start + step * i / slices; }, full);
  const bool outside = q->orientation == GLU_OUTSIDE;

  if (q->normals != GLU_NONE) glNormal3f(0.0f, 0.0f, outside ? 1.0f : -1.0f);

  auto radius = [&](int j) { return static_cast<float>(outerRadius - dr * (static_cast<float>(j) / loops)); };
  // A vertex at radius r on edge i; texture coordinates map the outer circle to [0,1]^2.
  auto vertex = [&](float r, int i) {
    if (q->texture) {
      const float tr = static_cast<float>(r / outerRadius / 2);
      glTexCoord2f(static_cast<float>(tr * a.s[i] + 0.5), static_cast<float>(tr * a.c[i] + 0.5));
    }
    glVertex3f(r * a.s[i], r * a.c[i], 0.0f);
  };

  switch (q->drawStyle) {
    case GLU_FILL: {
      int rings = loops;
      if (innerRadius == 0.0) {
        // The innermost ring is a fan around the centre.
        rings = loops - 1;
        glBegin(GL_TRIANGLE_FAN);
        if (q->texture) glTexCoord2f(0.5f, 0.5f);
        glVertex3f(0.0f, 0.0f, 0.0f);
        const float r = radius(loops - 1);
        if (outside)
          for (int i = slices; i >= 0; i--) vertex(r, i);
        else
          for (int i = 0; i <= slices; i++) vertex(r, i);
        glEnd();
      }
      for (int j = 0; j < rings; j++) {
        const float r0 = radius(j), r1 = radius(j + 1);
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= slices; i++) {
          if (outside) {
            vertex(r0, i);
            vertex(r1, i);
          } else {
            vertex(r1, i);
            vertex(r0, i);
          }
        }
        glEnd();
      }
      break;
    }
    case GLU_POINT:
      glBegin(GL_POINTS);
      for (int i = 0; i < edges; i++)
        for (int j = 0; j <= loops; j++) vertex(radius(j), i);
      glEnd();
      break;
    case GLU_LINE:
      if (innerRadius == outerRadius) {
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; i++) {
          if (q->texture) glTexCoord2f(a.s[i] / 2 + 0.5f, a.c[i] / 2 + 0.5f);
          glVertex3f(static_cast<float>(innerRadius * a.s[i]), static_cast<float>(innerRadius * a.c[i]),
                     0.0f);
        }
        glEnd();
        break;
      }
      for (int j = 0; j <= loops; j++) {
        const float r = radius(j);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; i++) vertex(r, i);
        glEnd();
      }
      for (int i = 0; i < edges; i++) {
        glBegin(GL_LINE_STRIP);
        for (int j = 0; j <= loops; j++) vertex(radius(j), i);
        glEnd();
      }
      break;
    case GLU_SILHOUETTE:
      // The two straight edges of a partial disk, then the outer and inner circles.
      if (sweepAngle < 360.0) {
        for (int i = 0; i <= slices; i += slices) {
          glBegin(GL_LINE_STRIP);
          for (int j = 0; j <= loops; j++) vertex(radius(j), i);
          glEnd();
        }
      }
      for (int j = 0; j <= loops; j += loops) {
        const float r = radius(j);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; i++) vertex(r, i);
        glEnd();
        if (innerRadius == outerRadius) break;
      }
      break;
    default: break;
  }
}

// Section 6.7: a full disk.
void GLAPIENTRY gluDisk(GLUquadric* q, GLdouble innerRadius, GLdouble outerRadius, GLint slices,
                        GLint loops) {
  gluPartialDisk(q, innerRadius, outerRadius, slices, loops, 0.0, 360.0);
}

// ---------------------------------------------------------------------------------------------
// Section 6.5: a sphere around the origin, `slices` subdivisions around z and `stacks` along
// it, stack 0 at +z.
void GLAPIENTRY gluSphere(GLUquadric* q, GLdouble radius, GLint slices, GLint stacks) {
  if (slices > kMaxDivisions) slices = kMaxDivisions;
  if (stacks > kMaxDivisions) stacks = kMaxDivisions;
  if (slices < 2 || stacks < 1 || radius < 0.0) {
    quadricError(q, GLU_INVALID_VALUE);
    return;
  }
  const bool outside = q->orientation == GLU_OUTSIDE;
  const float sign = outside ? 1.0f : -1.0f;

  // Around z (index i): positions and smooth normals at the slice edges, flat normals half a
  // slice back.
  const Circle ring = circle(
      slices, [&](int i) { return 2 * kPi * i / slices; }, true);
  const Circle ringFlat = circle(
      slices, [&](int i) { return 2 * kPi * (i - 0.5) / slices; }, true);
  // Along z (index j): the polar angle from +z.
  std::vector<float> rs(stacks + 1), rz(stacks + 1), ns(stacks + 1), nz(stacks + 1), fs(stacks + 1),
      fz(stacks + 1);
  for (int j = 0; j <= stacks; j++) {
    const float a = static_cast<float>(kPi * j / stacks);
    const float af = static_cast<float>(kPi * (j - 0.5) / stacks);
    rs[j] = static_cast<float>(radius * std::sin(static_cast<double>(a)));
    rz[j] = static_cast<float>(radius * std::cos(static_cast<double>(a)));
    ns[j] = sign * fsin(a);
    nz[j] = sign * fcos(a);
    fs[j] = sign * fsin(af);
    fz[j] = sign * fcos(af);
  }
  rs[0] = 0;  // the poles are points
  rs[stacks] = 0;

  auto vertex = [&](int i, int j) { glVertex3f(rs[j] * ring.s[i], rs[j] * ring.c[i], rz[j]); };
  auto texVertex = [&](int i, int j) {
    if (q->texture) glTexCoord2f(1 - static_cast<float>(i) / slices, 1 - static_cast<float>(j) / stacks);
    vertex(i, j);
  };
  auto smoothNormal = [&](int i, int j) { glNormal3f(ring.s[i] * ns[j], ring.c[i] * ns[j], nz[j]); };
  auto flatNormal = [&](int i, int j) { glNormal3f(ringFlat.s[i] * fs[j], ringFlat.c[i] * fs[j], fz[j]); };

  switch (q->drawStyle) {
    case GLU_FILL: {
      int first = 0, last = stacks;
      if (!q->texture) {
        // Without texture coordinates the caps are fans around the poles (with texturing the
        // pole needs a different s for every triangle, so it stays in the quad strips).
        first = 1;
        last = stacks - 1;
        // North cap.
        if (q->normals == GLU_SMOOTH) glNormal3f(0.0f, 0.0f, nz[0]);
        glBegin(GL_TRIANGLE_FAN);
        glVertex3f(0.0f, 0.0f, static_cast<float>(radius));
        if (outside) {
          for (int i = slices; i >= 0; i--) {
            if (q->normals == GLU_SMOOTH)
              smoothNormal(i, 1);
            else if (q->normals == GLU_FLAT && i != slices)
              flatNormal(i + 1, 1);
            vertex(i, 1);
          }
        } else {
          for (int i = 0; i <= slices; i++) {
            if (q->normals == GLU_SMOOTH)
              smoothNormal(i, 1);
            else if (q->normals == GLU_FLAT)
              flatNormal(i, 1);
            vertex(i, 1);
          }
        }
        glEnd();
        // South cap.
        // The reference GLU takes this normal's x and y from the slice table at index
        // `stacks`; sin(pi) in single precision makes them tiny but not zero.
        if (q->normals == GLU_SMOOTH) {
          const int k = stacks <= slices ? stacks : 0;
          glNormal3f(ring.s[k] * ns[stacks], ring.c[k] * ns[stacks], nz[stacks]);
        }
        glBegin(GL_TRIANGLE_FAN);
        glVertex3f(0.0f, 0.0f, static_cast<float>(-radius));
        if (outside) {
          for (int i = 0; i <= slices; i++) {
            if (q->normals == GLU_SMOOTH)
              smoothNormal(i, stacks - 1);
            else if (q->normals == GLU_FLAT)
              flatNormal(i, stacks);
            vertex(i, stacks - 1);
          }
        } else {
          for (int i = slices; i >= 0; i--) {
            if (q->normals == GLU_SMOOTH)
              smoothNormal(i, stacks - 1);
            else if (q->normals == GLU_FLAT && i != slices)
              flatNormal(i + 1, stacks);
            vertex(i, stacks - 1);
          }
        }
        glEnd();
      }
      // One quad strip per stack: for each slice edge the lower vertex, then the upper one
      // (the other way round inside). Flat normals go with the second vertex of each pair,
      // which is the provoking vertex of the quad that pair closes.
      for (int j = first; j < last; j++) {
        const int a = outside ? j + 1 : j, b = outside ? j : j + 1;
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= slices; i++) {
          if (q->normals == GLU_SMOOTH) smoothNormal(i, a);
          texVertex(i, a);
          if (q->normals == GLU_SMOOTH)
            smoothNormal(i, b);
          else if (q->normals == GLU_FLAT)
            flatNormal(i, j + 1);
          texVertex(i, b);
        }
        glEnd();
      }
      break;
    }
    case GLU_POINT:
      // Smooth normals for GLU_FLAT too (see gluCylinder).
      glBegin(GL_POINTS);
      for (int j = 0; j <= stacks; j++) {
        for (int i = 0; i < slices; i++) {
          if (q->normals != GLU_NONE) smoothNormal(i, j);
          texVertex(i, j);
        }
      }
      glEnd();
      break;
    case GLU_LINE:
    case GLU_SILHOUETTE:
      // The rings between the poles, then the meridians from +z to -z. A sphere's silhouette
      // is drawn like its lines, with GLU_FLAT normals as for GLU_LINE (the reference GLU
      // sends uninitialised values for GLU_SILHOUETTE with GLU_FLAT).
      for (int j = 1; j < stacks; j++) {
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; i++) {
          if (q->normals == GLU_FLAT)
            glNormal3f(ringFlat.s[i] * ns[j], ringFlat.c[i] * ns[j], nz[j]);
          else if (q->normals == GLU_SMOOTH)
            smoothNormal(i, j);
          texVertex(i, j);
        }
        glEnd();
      }
      for (int i = 0; i < slices; i++) {
        glBegin(GL_LINE_STRIP);
        for (int j = 0; j <= stacks; j++) {
          if (q->normals == GLU_FLAT)
            glNormal3f(ring.s[i] * fs[j], ring.c[i] * fs[j], fz[j]);
          else if (q->normals == GLU_SMOOTH)
            smoothNormal(i, j);
          if (q->texture)
            glTexCoord2f(1 - static_cast<float>(i) / slices, 1 - static_cast<float>(j) / stacks);
          glVertex3f(ring.s[i] * rs[j], ring.c[i] * rs[j], rz[j]);
        }
        glEnd();
      }
      break;
    default: break;
  }
}

}  // extern "C"
