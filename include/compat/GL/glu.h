/*
 * Tessel compatibility header: <GL/glu.h>
 *
 * Declares the OpenGL Utility library, version 1.3: matrix helpers, image
 * scaling and mipmap building, quadrics, the polygon tessellator and the NURBS
 * interface.  Tessel provides the definitions in its own libraries; this file
 * only declares them.  Written for Tessel; the names and numbers are those
 * fixed by the GLU 1.3 specification.
 *
 * Usable from C (C89/C99 and later) and from C++.
 */
#if !defined(TESSEL_COMPAT_GL_GLU_H) && !defined(__glu_h__) && !defined(__GLU_H__)
#define TESSEL_COMPAT_GL_GLU_H 1
/* The traditional guards, so that another glu.h included later is skipped. */
#define __glu_h__ 1
#define __GLU_H__ 1

#include <GL/gl.h> /* types, TESSEL_GLAPI, TESSEL_APIENTRY, CALLBACK */

/* Normally set by Tessel's gl.h; repeated here for the case where another
 * vendor's gl.h was included first (and ours was therefore skipped). */
#ifndef TESSEL_GLAPI
#if defined(__GNUC__) || defined(__clang__)
#define TESSEL_GLAPI extern __attribute__((visibility("default")))
#else
#define TESSEL_GLAPI extern
#endif
#endif
#ifndef TESSEL_APIENTRY
#define TESSEL_APIENTRY
#endif
#ifndef CALLBACK
#define CALLBACK
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Versions ----------------------------------------------------------- */

#define GLU_VERSION_1_1 1
#define GLU_VERSION_1_2 1
#define GLU_VERSION_1_3 1

/* ---- Enumerants --------------------------------------------------------- */

/* Boolean values */
#define GLU_FALSE 0
#define GLU_TRUE 1

/* gluGetString names */
#define GLU_VERSION 100800
#define GLU_EXTENSIONS 100801

/* Error codes (gluErrorString also accepts the GL error codes) */
#define GLU_INVALID_ENUM 100900
#define GLU_INVALID_VALUE 100901
#define GLU_OUT_OF_MEMORY 100902
#define GLU_INCOMPATIBLE_GL_VERSION 100903
#define GLU_INVALID_OPERATION 100904

/* Quadrics: draw styles (gluQuadricDrawStyle); GLU_FILL is also a NURBS display mode */
#define GLU_POINT 100010
#define GLU_LINE 100011
#define GLU_FILL 100012
#define GLU_SILHOUETTE 100013

/* Quadrics: normals (gluQuadricNormals) */
#define GLU_SMOOTH 100000
#define GLU_FLAT 100001
#define GLU_NONE 100002

/* Quadrics: orientation (gluQuadricOrientation) */
#define GLU_OUTSIDE 100020
#define GLU_INSIDE 100021

/* Error callback, shared by quadrics, tessellators and NURBS objects */
#define GLU_ERROR 100103

/* Tessellator: callbacks (gluTessCallback) */
#define GLU_TESS_BEGIN 100100
#define GLU_TESS_VERTEX 100101
#define GLU_TESS_END 100102
#define GLU_TESS_ERROR 100103
#define GLU_TESS_EDGE_FLAG 100104
#define GLU_TESS_COMBINE 100105
#define GLU_TESS_BEGIN_DATA 100106
#define GLU_TESS_VERTEX_DATA 100107
#define GLU_TESS_END_DATA 100108
#define GLU_TESS_ERROR_DATA 100109
#define GLU_TESS_EDGE_FLAG_DATA 100110
#define GLU_TESS_COMBINE_DATA 100111

/* Tessellator: GLU 1.1 callback names (same values as GLU_TESS_*) */
#define GLU_BEGIN 100100
#define GLU_VERTEX 100101
#define GLU_END 100102
#define GLU_EDGE_FLAG 100104

/* Tessellator: GLU 1.1 contour types (gluNextContour) */
#define GLU_CW 100120
#define GLU_CCW 100121
#define GLU_INTERIOR 100122
#define GLU_EXTERIOR 100123
#define GLU_UNKNOWN 100124

/* Tessellator: winding rules (GLU_TESS_WINDING_RULE) */
#define GLU_TESS_WINDING_ODD 100130
#define GLU_TESS_WINDING_NONZERO 100131
#define GLU_TESS_WINDING_POSITIVE 100132
#define GLU_TESS_WINDING_NEGATIVE 100133
#define GLU_TESS_WINDING_ABS_GEQ_TWO 100134

/* Tessellator: properties (gluTessProperty, gluGetTessProperty) */
#define GLU_TESS_WINDING_RULE 100140
#define GLU_TESS_BOUNDARY_ONLY 100141
#define GLU_TESS_TOLERANCE 100142

/* Tessellator: errors, by number and by meaning */
#define GLU_TESS_ERROR1 100151
#define GLU_TESS_ERROR2 100152
#define GLU_TESS_ERROR3 100153
#define GLU_TESS_ERROR4 100154
#define GLU_TESS_ERROR5 100155
#define GLU_TESS_ERROR6 100156
#define GLU_TESS_ERROR7 100157
#define GLU_TESS_ERROR8 100158
#define GLU_TESS_MISSING_BEGIN_POLYGON 100151
#define GLU_TESS_MISSING_BEGIN_CONTOUR 100152
#define GLU_TESS_MISSING_END_POLYGON 100153
#define GLU_TESS_MISSING_END_CONTOUR 100154
#define GLU_TESS_COORD_TOO_LARGE 100155
#define GLU_TESS_NEED_COMBINE_CALLBACK 100156

/* Tessellator: largest accepted coordinate magnitude */
#define GLU_TESS_MAX_COORD 1.0e150

/* NURBS: properties (gluNurbsProperty, gluGetNurbsProperty) */
#define GLU_AUTO_LOAD_MATRIX 100200
#define GLU_CULLING 100201
#define GLU_PARAMETRIC_TOLERANCE 100202
#define GLU_SAMPLING_TOLERANCE 100203
#define GLU_DISPLAY_MODE 100204
#define GLU_SAMPLING_METHOD 100205
#define GLU_U_STEP 100206
#define GLU_V_STEP 100207
#define GLU_NURBS_MODE 100160

/* NURBS: GLU_NURBS_MODE values */
#define GLU_NURBS_TESSELLATOR 100161
#define GLU_NURBS_RENDERER 100162

/* NURBS: GLU_SAMPLING_METHOD values */
#define GLU_OBJECT_PARAMETRIC_ERROR 100208
#define GLU_OBJECT_PATH_LENGTH 100209
#define GLU_PATH_LENGTH 100215
#define GLU_PARAMETRIC_ERROR 100216
#define GLU_DOMAIN_DISTANCE 100217

/* NURBS: GLU_DISPLAY_MODE values (besides GLU_FILL) */
#define GLU_OUTLINE_POLYGON 100240
#define GLU_OUTLINE_PATCH 100241

/* NURBS: trimming curve types (gluPwlCurve, gluNurbsCurve) */
#define GLU_MAP1_TRIM_2 100210
#define GLU_MAP1_TRIM_3 100211

/* NURBS: callbacks (gluNurbsCallback) */
#define GLU_NURBS_ERROR 100103
#define GLU_NURBS_BEGIN 100164
#define GLU_NURBS_VERTEX 100165
#define GLU_NURBS_NORMAL 100166
#define GLU_NURBS_COLOR 100167
#define GLU_NURBS_TEXTURE_COORD 100168
#define GLU_NURBS_END 100169
#define GLU_NURBS_BEGIN_DATA 100170
#define GLU_NURBS_VERTEX_DATA 100171
#define GLU_NURBS_NORMAL_DATA 100172
#define GLU_NURBS_COLOR_DATA 100173
#define GLU_NURBS_TEXTURE_COORD_DATA 100174
#define GLU_NURBS_END_DATA 100175

/* NURBS: the same names as spelled by the GLU_EXT_nurbs_tessellator and
 * GLU_EXT_object_space_tess extensions (aliases only) */
#define GLU_NURBS_MODE_EXT 100160
#define GLU_NURBS_TESSELLATOR_EXT 100161
#define GLU_NURBS_RENDERER_EXT 100162
#define GLU_NURBS_BEGIN_EXT 100164
#define GLU_NURBS_VERTEX_EXT 100165
#define GLU_NURBS_NORMAL_EXT 100166
#define GLU_NURBS_COLOR_EXT 100167
#define GLU_NURBS_TEX_COORD_EXT 100168
#define GLU_NURBS_END_EXT 100169
#define GLU_NURBS_BEGIN_DATA_EXT 100170
#define GLU_NURBS_VERTEX_DATA_EXT 100171
#define GLU_NURBS_NORMAL_DATA_EXT 100172
#define GLU_NURBS_COLOR_DATA_EXT 100173
#define GLU_NURBS_TEX_COORD_DATA_EXT 100174
#define GLU_NURBS_END_DATA_EXT 100175
#define GLU_OBJECT_PARAMETRIC_ERROR_EXT 100208
#define GLU_OBJECT_PATH_LENGTH_EXT 100209

/* NURBS: error codes reported to the GLU_NURBS_ERROR callback */
#define GLU_NURBS_ERROR1 100251
#define GLU_NURBS_ERROR2 100252
#define GLU_NURBS_ERROR3 100253
#define GLU_NURBS_ERROR4 100254
#define GLU_NURBS_ERROR5 100255
#define GLU_NURBS_ERROR6 100256
#define GLU_NURBS_ERROR7 100257
#define GLU_NURBS_ERROR8 100258
#define GLU_NURBS_ERROR9 100259
#define GLU_NURBS_ERROR10 100260
#define GLU_NURBS_ERROR11 100261
#define GLU_NURBS_ERROR12 100262
#define GLU_NURBS_ERROR13 100263
#define GLU_NURBS_ERROR14 100264
#define GLU_NURBS_ERROR15 100265
#define GLU_NURBS_ERROR16 100266
#define GLU_NURBS_ERROR17 100267
#define GLU_NURBS_ERROR18 100268
#define GLU_NURBS_ERROR19 100269
#define GLU_NURBS_ERROR20 100270
#define GLU_NURBS_ERROR21 100271
#define GLU_NURBS_ERROR22 100272
#define GLU_NURBS_ERROR23 100273
#define GLU_NURBS_ERROR24 100274
#define GLU_NURBS_ERROR25 100275
#define GLU_NURBS_ERROR26 100276
#define GLU_NURBS_ERROR27 100277
#define GLU_NURBS_ERROR28 100278
#define GLU_NURBS_ERROR29 100279
#define GLU_NURBS_ERROR30 100280
#define GLU_NURBS_ERROR31 100281
#define GLU_NURBS_ERROR32 100282
#define GLU_NURBS_ERROR33 100283
#define GLU_NURBS_ERROR34 100284
#define GLU_NURBS_ERROR35 100285
#define GLU_NURBS_ERROR36 100286
#define GLU_NURBS_ERROR37 100287

/* ---- Object types ------------------------------------------------------- */

/* Opaque handles; the structures are private to the implementation.  The
 * *Obj names are the GLU 1.0/1.1 spellings of the same types. */
typedef struct GLUquadric GLUquadric;
typedef struct GLUtesselator GLUtesselator;
typedef struct GLUnurbs GLUnurbs;

typedef GLUquadric GLUquadricObj;
typedef GLUtesselator GLUtesselatorObj;
typedef GLUtesselator GLUtriangulatorObj;
typedef GLUnurbs GLUnurbsObj;

/* Generic callback type taken by gluQuadricCallback, gluTessCallback and
 * gluNurbsCallback; the real signature depends on the callback name, so
 * programs cast their function to this type. */
typedef void(TESSEL_APIENTRY* _GLUfuncptr)(void);

/* ---- Errors and strings ------------------------------------------------- */

TESSEL_GLAPI const GLubyte* TESSEL_APIENTRY gluErrorString(GLenum errorCode);
TESSEL_GLAPI const GLubyte* TESSEL_APIENTRY gluGetString(GLenum name);
TESSEL_GLAPI GLboolean TESSEL_APIENTRY gluCheckExtension(const GLubyte* extName, const GLubyte* extString);

/* ---- Viewing matrices and coordinate projection ------------------------- */

TESSEL_GLAPI void TESSEL_APIENTRY gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);
TESSEL_GLAPI void TESSEL_APIENTRY gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear,
                                                 GLdouble zFar);
TESSEL_GLAPI void TESSEL_APIENTRY gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX,
                                            GLdouble centerY, GLdouble centerZ, GLdouble upX, GLdouble upY,
                                            GLdouble upZ);
TESSEL_GLAPI void TESSEL_APIENTRY gluPickMatrix(GLdouble x, GLdouble y, GLdouble deltaX, GLdouble deltaY,
                                                GLint* viewport);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluProject(GLdouble objX, GLdouble objY, GLdouble objZ,
                                              const GLdouble* model, const GLdouble* proj, const GLint* view,
                                              GLdouble* winX, GLdouble* winY, GLdouble* winZ);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ,
                                                const GLdouble* model, const GLdouble* proj,
                                                const GLint* view, GLdouble* objX, GLdouble* objY,
                                                GLdouble* objZ);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW,
                                                 const GLdouble* model, const GLdouble* proj,
                                                 const GLint* view, GLdouble nearVal, GLdouble farVal,
                                                 GLdouble* objX, GLdouble* objY, GLdouble* objZ,
                                                 GLdouble* objW);

/* ---- Images and mipmaps ------------------------------------------------- */

TESSEL_GLAPI GLint TESSEL_APIENTRY gluScaleImage(GLenum format, GLsizei widthIn, GLsizei heightIn,
                                                 GLenum typeIn, const void* dataIn, GLsizei widthOut,
                                                 GLsizei heightOut, GLenum typeOut, GLvoid* dataOut);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                                     GLenum format, GLenum type, const void* data);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                                     GLsizei height, GLenum format, GLenum type,
                                                     const void* data);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluBuild3DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                                     GLsizei height, GLsizei depth, GLenum format,
                                                     GLenum type, const void* data);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluBuild1DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width,
                                                          GLenum format, GLenum type, GLint level, GLint base,
                                                          GLint max, const void* data);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluBuild2DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width,
                                                          GLsizei height, GLenum format, GLenum type,
                                                          GLint level, GLint base, GLint max,
                                                          const void* data);
TESSEL_GLAPI GLint TESSEL_APIENTRY gluBuild3DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width,
                                                          GLsizei height, GLsizei depth, GLenum format,
                                                          GLenum type, GLint level, GLint base, GLint max,
                                                          const void* data);

/* ---- Quadrics ----------------------------------------------------------- */

TESSEL_GLAPI GLUquadric* TESSEL_APIENTRY gluNewQuadric(void);
TESSEL_GLAPI void TESSEL_APIENTRY gluDeleteQuadric(GLUquadric* quad);
TESSEL_GLAPI void TESSEL_APIENTRY gluQuadricDrawStyle(GLUquadric* quad, GLenum draw);
TESSEL_GLAPI void TESSEL_APIENTRY gluQuadricNormals(GLUquadric* quad, GLenum normal);
TESSEL_GLAPI void TESSEL_APIENTRY gluQuadricOrientation(GLUquadric* quad, GLenum orientation);
TESSEL_GLAPI void TESSEL_APIENTRY gluQuadricTexture(GLUquadric* quad, GLboolean texture);
TESSEL_GLAPI void TESSEL_APIENTRY gluQuadricCallback(GLUquadric* quad, GLenum which, _GLUfuncptr fn);
TESSEL_GLAPI void TESSEL_APIENTRY gluSphere(GLUquadric* quad, GLdouble radius, GLint slices, GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY gluCylinder(GLUquadric* quad, GLdouble base, GLdouble top, GLdouble height,
                                              GLint slices, GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY gluDisk(GLUquadric* quad, GLdouble inner, GLdouble outer, GLint slices,
                                          GLint loops);
TESSEL_GLAPI void TESSEL_APIENTRY gluPartialDisk(GLUquadric* quad, GLdouble inner, GLdouble outer,
                                                 GLint slices, GLint loops, GLdouble start, GLdouble sweep);

/* ---- Polygon tessellation ----------------------------------------------- */

TESSEL_GLAPI GLUtesselator* TESSEL_APIENTRY gluNewTess(void);
TESSEL_GLAPI void TESSEL_APIENTRY gluDeleteTess(GLUtesselator* tess);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessBeginPolygon(GLUtesselator* tess, GLvoid* data);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessBeginContour(GLUtesselator* tess);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessVertex(GLUtesselator* tess, GLdouble* location, GLvoid* data);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessEndContour(GLUtesselator* tess);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessEndPolygon(GLUtesselator* tess);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessProperty(GLUtesselator* tess, GLenum which, GLdouble data);
TESSEL_GLAPI void TESSEL_APIENTRY gluGetTessProperty(GLUtesselator* tess, GLenum which, GLdouble* data);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessNormal(GLUtesselator* tess, GLdouble valueX, GLdouble valueY,
                                                GLdouble valueZ);
TESSEL_GLAPI void TESSEL_APIENTRY gluTessCallback(GLUtesselator* tess, GLenum which, _GLUfuncptr fn);

/* GLU 1.1 style polygon interface (kept by GLU 1.3 for old programs) */
TESSEL_GLAPI void TESSEL_APIENTRY gluBeginPolygon(GLUtesselator* tess);
TESSEL_GLAPI void TESSEL_APIENTRY gluNextContour(GLUtesselator* tess, GLenum type);
TESSEL_GLAPI void TESSEL_APIENTRY gluEndPolygon(GLUtesselator* tess);

/* ---- NURBS curves and surfaces ------------------------------------------ */

TESSEL_GLAPI GLUnurbs* TESSEL_APIENTRY gluNewNurbsRenderer(void);
TESSEL_GLAPI void TESSEL_APIENTRY gluDeleteNurbsRenderer(GLUnurbs* nurb);
TESSEL_GLAPI void TESSEL_APIENTRY gluNurbsProperty(GLUnurbs* nurb, GLenum property, GLfloat value);
TESSEL_GLAPI void TESSEL_APIENTRY gluGetNurbsProperty(GLUnurbs* nurb, GLenum property, GLfloat* data);
TESSEL_GLAPI void TESSEL_APIENTRY gluLoadSamplingMatrices(GLUnurbs* nurb, const GLfloat* model,
                                                          const GLfloat* perspective, const GLint* view);
TESSEL_GLAPI void TESSEL_APIENTRY gluNurbsCallback(GLUnurbs* nurb, GLenum which, _GLUfuncptr fn);
TESSEL_GLAPI void TESSEL_APIENTRY gluNurbsCallbackData(GLUnurbs* nurb, GLvoid* userData);
TESSEL_GLAPI void TESSEL_APIENTRY gluNurbsCallbackDataEXT(GLUnurbs* nurb, GLvoid* userData);
TESSEL_GLAPI void TESSEL_APIENTRY gluBeginCurve(GLUnurbs* nurb);
TESSEL_GLAPI void TESSEL_APIENTRY gluNurbsCurve(GLUnurbs* nurb, GLint knotCount, GLfloat* knots, GLint stride,
                                                GLfloat* control, GLint order, GLenum type);
TESSEL_GLAPI void TESSEL_APIENTRY gluEndCurve(GLUnurbs* nurb);
TESSEL_GLAPI void TESSEL_APIENTRY gluBeginSurface(GLUnurbs* nurb);
TESSEL_GLAPI void TESSEL_APIENTRY gluNurbsSurface(GLUnurbs* nurb, GLint sKnotCount, GLfloat* sKnots,
                                                  GLint tKnotCount, GLfloat* tKnots, GLint sStride,
                                                  GLint tStride, GLfloat* control, GLint sOrder, GLint tOrder,
                                                  GLenum type);
TESSEL_GLAPI void TESSEL_APIENTRY gluEndSurface(GLUnurbs* nurb);
TESSEL_GLAPI void TESSEL_APIENTRY gluBeginTrim(GLUnurbs* nurb);
TESSEL_GLAPI void TESSEL_APIENTRY gluPwlCurve(GLUnurbs* nurb, GLint count, GLfloat* data, GLint stride,
                                              GLenum type);
TESSEL_GLAPI void TESSEL_APIENTRY gluEndTrim(GLUnurbs* nurb);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* TESSEL_COMPAT_GL_GLU_H */
