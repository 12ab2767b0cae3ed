/*
 * Tessel compatibility header: <GL/gl.h>
 *
 * Declares the OpenGL 1.1 API (every enumerant and every entry point of the
 * 1.1 specification) plus the handful of OpenGL 1.2/1.3 names that classic
 * course programs use.  Tessel provides the definitions in its own libraries;
 * this file only declares them.  Written for Tessel; the names and numbers are
 * those fixed by the OpenGL specifications.
 *
 * Usable from C (C89/C99 and later) and from C++.
 */
#if !defined(TESSEL_COMPAT_GL_GL_H) && !defined(__gl_h_) && !defined(__GL_H__)
#define TESSEL_COMPAT_GL_GL_H 1
/* The traditional guards, so that another vendor's gl.h included after this
 * one is skipped instead of declaring everything a second time. */
#define __gl_h_ 1
#define __GL_H__ 1

#include <stddef.h> /* ptrdiff_t */

/* ---- Linkage and calling-convention macros ------------------------------ */

/* Export decoration of every Tessel GL/GLU/GLUT entry point. */
#ifndef TESSEL_GLAPI
#if defined(__GNUC__) || defined(__clang__)
#define TESSEL_GLAPI extern __attribute__((visibility("default")))
#else
#define TESSEL_GLAPI extern
#endif
#endif

/* Calling convention of the entry points: the platform default on Linux. */
#ifndef TESSEL_APIENTRY
#define TESSEL_APIENTRY
#endif

/* The customary spellings programs (and glext.h) expect to find. */
#ifndef GLAPI
#define GLAPI TESSEL_GLAPI
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#ifndef APIENTRY
#define APIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY*
#endif
#ifndef GLAPIENTRYP
#define GLAPIENTRYP GLAPIENTRY*
#endif
#ifndef CALLBACK
#define CALLBACK
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* 1.1 is declared here; GL/glext.h, included at the end, adds 1.2 to 3.3. */
#define GL_VERSION_1_1 1

/* ---- Scalar types -------------------------------------------------------- */

#ifndef TESSEL_GL_SCALAR_TYPES /* shared with GL/glcorearb.h */
#define TESSEL_GL_SCALAR_TYPES 1
typedef unsigned int GLenum;     /* enumerant                          */
typedef unsigned char GLboolean; /* GL_FALSE or GL_TRUE                 */
typedef unsigned int GLbitfield; /* OR of *_BIT masks                   */
typedef void GLvoid;
typedef signed char GLbyte;      /* 8-bit signed                        */
typedef short GLshort;           /* 16-bit signed                       */
typedef int GLint;               /* 32-bit signed                       */
typedef int GLsizei;             /* non-negative size / count           */
typedef unsigned char GLubyte;   /* 8-bit unsigned                      */
typedef unsigned short GLushort; /* 16-bit unsigned                     */
typedef unsigned int GLuint;     /* 32-bit unsigned                     */
typedef float GLfloat;
typedef float GLclampf; /* float clamped to [0, 1]             */
typedef double GLdouble;
typedef double GLclampd; /* double clamped to [0, 1]            */
typedef char GLchar;
typedef ptrdiff_t GLintptr;
typedef ptrdiff_t GLsizeiptr;
#endif

/* ==========================================================================
 * Enumerants, OpenGL 1.1 (grouped after the chapters of the 1.1 spec)
 * ========================================================================== */

/* -- Chapter 2: OpenGL operation -- */

/* Boolean values */
#define GL_FALSE 0
#define GL_TRUE 1

/* Component types (vertex arrays, pixels, glCallLists) */
#define GL_BYTE 0x1400
#define GL_UNSIGNED_BYTE 0x1401
#define GL_SHORT 0x1402
#define GL_UNSIGNED_SHORT 0x1403
#define GL_INT 0x1404
#define GL_UNSIGNED_INT 0x1405
#define GL_FLOAT 0x1406
#define GL_2_BYTES 0x1407
#define GL_3_BYTES 0x1408
#define GL_4_BYTES 0x1409
#define GL_DOUBLE 0x140A

/* glGetError codes */
#define GL_NO_ERROR 0
#define GL_INVALID_ENUM 0x0500
#define GL_INVALID_VALUE 0x0501
#define GL_INVALID_OPERATION 0x0502
#define GL_STACK_OVERFLOW 0x0503
#define GL_STACK_UNDERFLOW 0x0504
#define GL_OUT_OF_MEMORY 0x0505

/* glBegin primitive modes */
#define GL_POINTS 0x0000
#define GL_LINES 0x0001
#define GL_LINE_LOOP 0x0002
#define GL_LINE_STRIP 0x0003
#define GL_TRIANGLES 0x0004
#define GL_TRIANGLE_STRIP 0x0005
#define GL_TRIANGLE_FAN 0x0006
#define GL_QUADS 0x0007
#define GL_QUAD_STRIP 0x0008
#define GL_POLYGON 0x0009

/* Vertex arrays: client-state capabilities */
#define GL_VERTEX_ARRAY 0x8074
#define GL_NORMAL_ARRAY 0x8075
#define GL_COLOR_ARRAY 0x8076
#define GL_INDEX_ARRAY 0x8077
#define GL_TEXTURE_COORD_ARRAY 0x8078
#define GL_EDGE_FLAG_ARRAY 0x8079

/* Vertex arrays: queries */
#define GL_VERTEX_ARRAY_SIZE 0x807A
#define GL_VERTEX_ARRAY_TYPE 0x807B
#define GL_VERTEX_ARRAY_STRIDE 0x807C
#define GL_VERTEX_ARRAY_POINTER 0x808E
#define GL_NORMAL_ARRAY_TYPE 0x807E
#define GL_NORMAL_ARRAY_STRIDE 0x807F
#define GL_NORMAL_ARRAY_POINTER 0x808F
#define GL_COLOR_ARRAY_SIZE 0x8081
#define GL_COLOR_ARRAY_TYPE 0x8082
#define GL_COLOR_ARRAY_STRIDE 0x8083
#define GL_COLOR_ARRAY_POINTER 0x8090
#define GL_INDEX_ARRAY_TYPE 0x8085
#define GL_INDEX_ARRAY_STRIDE 0x8086
#define GL_INDEX_ARRAY_POINTER 0x8091
#define GL_TEXTURE_COORD_ARRAY_SIZE 0x8088
#define GL_TEXTURE_COORD_ARRAY_TYPE 0x8089
#define GL_TEXTURE_COORD_ARRAY_STRIDE 0x808A
#define GL_TEXTURE_COORD_ARRAY_POINTER 0x8092
#define GL_EDGE_FLAG_ARRAY_STRIDE 0x808C
#define GL_EDGE_FLAG_ARRAY_POINTER 0x8093

/* glInterleavedArrays formats */
#define GL_V2F 0x2A20
#define GL_V3F 0x2A21
#define GL_C4UB_V2F 0x2A22
#define GL_C4UB_V3F 0x2A23
#define GL_C3F_V3F 0x2A24
#define GL_N3F_V3F 0x2A25
#define GL_C4F_N3F_V3F 0x2A26
#define GL_T2F_V3F 0x2A27
#define GL_T4F_V4F 0x2A28
#define GL_T2F_C4UB_V3F 0x2A29
#define GL_T2F_C3F_V3F 0x2A2A
#define GL_T2F_N3F_V3F 0x2A2B
#define GL_T2F_C4F_N3F_V3F 0x2A2C
#define GL_T4F_C4F_N3F_V4F 0x2A2D

/* Matrix stacks and viewport */
#define GL_MATRIX_MODE 0x0BA0
#define GL_MODELVIEW 0x1700
#define GL_PROJECTION 0x1701
#define GL_TEXTURE 0x1702
#define GL_MODELVIEW_MATRIX 0x0BA6
#define GL_PROJECTION_MATRIX 0x0BA7
#define GL_TEXTURE_MATRIX 0x0BA8
#define GL_MODELVIEW_STACK_DEPTH 0x0BA3
#define GL_PROJECTION_STACK_DEPTH 0x0BA4
#define GL_TEXTURE_STACK_DEPTH 0x0BA5
#define GL_NORMALIZE 0x0BA1
#define GL_VIEWPORT 0x0BA2
#define GL_DEPTH_RANGE 0x0B70

/* Texture coordinate generation */
#define GL_S 0x2000
#define GL_T 0x2001
#define GL_R 0x2002
#define GL_Q 0x2003
#define GL_TEXTURE_GEN_S 0x0C60
#define GL_TEXTURE_GEN_T 0x0C61
#define GL_TEXTURE_GEN_R 0x0C62
#define GL_TEXTURE_GEN_Q 0x0C63
#define GL_TEXTURE_GEN_MODE 0x2500
#define GL_OBJECT_PLANE 0x2501
#define GL_EYE_PLANE 0x2502
#define GL_OBJECT_LINEAR 0x2401
#define GL_EYE_LINEAR 0x2400
#define GL_SPHERE_MAP 0x2402

/* User clip planes */
#define GL_CLIP_PLANE0 0x3000
#define GL_CLIP_PLANE1 0x3001
#define GL_CLIP_PLANE2 0x3002
#define GL_CLIP_PLANE3 0x3003
#define GL_CLIP_PLANE4 0x3004
#define GL_CLIP_PLANE5 0x3005

/* Current vertex attributes and raster position */
#define GL_CURRENT_COLOR 0x0B00
#define GL_CURRENT_INDEX 0x0B01
#define GL_CURRENT_NORMAL 0x0B02
#define GL_CURRENT_TEXTURE_COORDS 0x0B03
#define GL_CURRENT_RASTER_COLOR 0x0B04
#define GL_CURRENT_RASTER_INDEX 0x0B05
#define GL_CURRENT_RASTER_TEXTURE_COORDS 0x0B06
#define GL_CURRENT_RASTER_POSITION 0x0B07
#define GL_CURRENT_RASTER_POSITION_VALID 0x0B08
#define GL_CURRENT_RASTER_DISTANCE 0x0B09

/* Faces (lighting, culling, polygon mode, draw buffers) */
#define GL_FRONT 0x0404
#define GL_BACK 0x0405
#define GL_FRONT_AND_BACK 0x0408

/* Lighting: enable and lights */
#define GL_LIGHTING 0x0B50
#define GL_LIGHT0 0x4000
#define GL_LIGHT1 0x4001
#define GL_LIGHT2 0x4002
#define GL_LIGHT3 0x4003
#define GL_LIGHT4 0x4004
#define GL_LIGHT5 0x4005
#define GL_LIGHT6 0x4006
#define GL_LIGHT7 0x4007

/* Lighting: light and material parameters */
#define GL_AMBIENT 0x1200
#define GL_DIFFUSE 0x1201
#define GL_SPECULAR 0x1202
#define GL_POSITION 0x1203
#define GL_SPOT_DIRECTION 0x1204
#define GL_SPOT_EXPONENT 0x1205
#define GL_SPOT_CUTOFF 0x1206
#define GL_CONSTANT_ATTENUATION 0x1207
#define GL_LINEAR_ATTENUATION 0x1208
#define GL_QUADRATIC_ATTENUATION 0x1209
#define GL_EMISSION 0x1600
#define GL_SHININESS 0x1601
#define GL_AMBIENT_AND_DIFFUSE 0x1602
#define GL_COLOR_INDEXES 0x1603

/* Lighting: light model, color material, shading */
#define GL_LIGHT_MODEL_LOCAL_VIEWER 0x0B51
#define GL_LIGHT_MODEL_TWO_SIDE 0x0B52
#define GL_LIGHT_MODEL_AMBIENT 0x0B53
#define GL_COLOR_MATERIAL 0x0B57
#define GL_COLOR_MATERIAL_FACE 0x0B55
#define GL_COLOR_MATERIAL_PARAMETER 0x0B56
#define GL_SHADE_MODEL 0x0B54
#define GL_FLAT 0x1D00
#define GL_SMOOTH 0x1D01

/* -- Chapter 3: rasterization -- */

/* Points and lines */
#define GL_POINT_SMOOTH 0x0B10
#define GL_POINT_SIZE 0x0B11
#define GL_POINT_SIZE_RANGE 0x0B12
#define GL_POINT_SIZE_GRANULARITY 0x0B13
#define GL_LINE_SMOOTH 0x0B20
#define GL_LINE_WIDTH 0x0B21
#define GL_LINE_WIDTH_RANGE 0x0B22
#define GL_LINE_WIDTH_GRANULARITY 0x0B23
#define GL_LINE_STIPPLE 0x0B24
#define GL_LINE_STIPPLE_PATTERN 0x0B25
#define GL_LINE_STIPPLE_REPEAT 0x0B26

/* Polygons */
#define GL_POINT 0x1B00
#define GL_LINE 0x1B01
#define GL_FILL 0x1B02
#define GL_CW 0x0900
#define GL_CCW 0x0901
#define GL_POLYGON_MODE 0x0B40
#define GL_POLYGON_SMOOTH 0x0B41
#define GL_POLYGON_STIPPLE 0x0B42
#define GL_EDGE_FLAG 0x0B43
#define GL_CULL_FACE 0x0B44
#define GL_CULL_FACE_MODE 0x0B45
#define GL_FRONT_FACE 0x0B46

/* Polygon offset */
#define GL_POLYGON_OFFSET_FACTOR 0x8038
#define GL_POLYGON_OFFSET_UNITS 0x2A00
#define GL_POLYGON_OFFSET_POINT 0x2A01
#define GL_POLYGON_OFFSET_LINE 0x2A02
#define GL_POLYGON_OFFSET_FILL 0x8037

/* glPixelStore parameters */
#define GL_UNPACK_SWAP_BYTES 0x0CF0
#define GL_UNPACK_LSB_FIRST 0x0CF1
#define GL_UNPACK_ROW_LENGTH 0x0CF2
#define GL_UNPACK_SKIP_ROWS 0x0CF3
#define GL_UNPACK_SKIP_PIXELS 0x0CF4
#define GL_UNPACK_ALIGNMENT 0x0CF5
#define GL_PACK_SWAP_BYTES 0x0D00
#define GL_PACK_LSB_FIRST 0x0D01
#define GL_PACK_ROW_LENGTH 0x0D02
#define GL_PACK_SKIP_ROWS 0x0D03
#define GL_PACK_SKIP_PIXELS 0x0D04
#define GL_PACK_ALIGNMENT 0x0D05

/* glPixelTransfer parameters and glPixelZoom state */
#define GL_MAP_COLOR 0x0D10
#define GL_MAP_STENCIL 0x0D11
#define GL_INDEX_SHIFT 0x0D12
#define GL_INDEX_OFFSET 0x0D13
#define GL_RED_SCALE 0x0D14
#define GL_RED_BIAS 0x0D15
#define GL_GREEN_SCALE 0x0D18
#define GL_GREEN_BIAS 0x0D19
#define GL_BLUE_SCALE 0x0D1A
#define GL_BLUE_BIAS 0x0D1B
#define GL_ALPHA_SCALE 0x0D1C
#define GL_ALPHA_BIAS 0x0D1D
#define GL_DEPTH_SCALE 0x0D1E
#define GL_DEPTH_BIAS 0x0D1F
#define GL_ZOOM_X 0x0D16
#define GL_ZOOM_Y 0x0D17

/* glPixelMap tables */
#define GL_PIXEL_MAP_I_TO_I 0x0C70
#define GL_PIXEL_MAP_S_TO_S 0x0C71
#define GL_PIXEL_MAP_I_TO_R 0x0C72
#define GL_PIXEL_MAP_I_TO_G 0x0C73
#define GL_PIXEL_MAP_I_TO_B 0x0C74
#define GL_PIXEL_MAP_I_TO_A 0x0C75
#define GL_PIXEL_MAP_R_TO_R 0x0C76
#define GL_PIXEL_MAP_G_TO_G 0x0C77
#define GL_PIXEL_MAP_B_TO_B 0x0C78
#define GL_PIXEL_MAP_A_TO_A 0x0C79

/* glPixelMap table sizes */
#define GL_PIXEL_MAP_I_TO_I_SIZE 0x0CB0
#define GL_PIXEL_MAP_S_TO_S_SIZE 0x0CB1
#define GL_PIXEL_MAP_I_TO_R_SIZE 0x0CB2
#define GL_PIXEL_MAP_I_TO_G_SIZE 0x0CB3
#define GL_PIXEL_MAP_I_TO_B_SIZE 0x0CB4
#define GL_PIXEL_MAP_I_TO_A_SIZE 0x0CB5
#define GL_PIXEL_MAP_R_TO_R_SIZE 0x0CB6
#define GL_PIXEL_MAP_G_TO_G_SIZE 0x0CB7
#define GL_PIXEL_MAP_B_TO_B_SIZE 0x0CB8
#define GL_PIXEL_MAP_A_TO_A_SIZE 0x0CB9

/* Pixel formats */
#define GL_COLOR_INDEX 0x1900
#define GL_STENCIL_INDEX 0x1901
#define GL_DEPTH_COMPONENT 0x1902
#define GL_RED 0x1903
#define GL_GREEN 0x1904
#define GL_BLUE 0x1905
#define GL_ALPHA 0x1906
#define GL_RGB 0x1907
#define GL_RGBA 0x1908
#define GL_LUMINANCE 0x1909
#define GL_LUMINANCE_ALPHA 0x190A
#define GL_BITMAP 0x1A00

/* glCopyPixels buffer types */
#define GL_COLOR 0x1800
#define GL_DEPTH 0x1801
#define GL_STENCIL 0x1802

/* Texture targets, proxies and bindings */
#define GL_TEXTURE_1D 0x0DE0
#define GL_TEXTURE_2D 0x0DE1
#define GL_PROXY_TEXTURE_1D 0x8063
#define GL_PROXY_TEXTURE_2D 0x8064
#define GL_TEXTURE_BINDING_1D 0x8068
#define GL_TEXTURE_BINDING_2D 0x8069

/* Texture object parameters */
#define GL_TEXTURE_MAG_FILTER 0x2800
#define GL_TEXTURE_MIN_FILTER 0x2801
#define GL_TEXTURE_WRAP_S 0x2802
#define GL_TEXTURE_WRAP_T 0x2803
#define GL_TEXTURE_BORDER_COLOR 0x1004
#define GL_TEXTURE_PRIORITY 0x8066
#define GL_TEXTURE_RESIDENT 0x8067

/* Texture filters and wrap modes */
#define GL_NEAREST 0x2600
#define GL_LINEAR 0x2601
#define GL_NEAREST_MIPMAP_NEAREST 0x2700
#define GL_LINEAR_MIPMAP_NEAREST 0x2701
#define GL_NEAREST_MIPMAP_LINEAR 0x2702
#define GL_LINEAR_MIPMAP_LINEAR 0x2703
#define GL_CLAMP 0x2900
#define GL_REPEAT 0x2901

/* Texture level parameters (glGetTexLevelParameter) */
#define GL_TEXTURE_WIDTH 0x1000
#define GL_TEXTURE_HEIGHT 0x1001
#define GL_TEXTURE_INTERNAL_FORMAT 0x1003
#define GL_TEXTURE_COMPONENTS 0x1003
#define GL_TEXTURE_BORDER 0x1005
#define GL_TEXTURE_RED_SIZE 0x805C
#define GL_TEXTURE_GREEN_SIZE 0x805D
#define GL_TEXTURE_BLUE_SIZE 0x805E
#define GL_TEXTURE_ALPHA_SIZE 0x805F
#define GL_TEXTURE_LUMINANCE_SIZE 0x8060
#define GL_TEXTURE_INTENSITY_SIZE 0x8061

/* Texture environment */
#define GL_TEXTURE_ENV 0x2300
#define GL_TEXTURE_ENV_MODE 0x2200
#define GL_TEXTURE_ENV_COLOR 0x2201
#define GL_MODULATE 0x2100
#define GL_DECAL 0x2101

/* Sized internal formats */
#define GL_ALPHA4 0x803B
#define GL_ALPHA8 0x803C
#define GL_ALPHA12 0x803D
#define GL_ALPHA16 0x803E
#define GL_LUMINANCE4 0x803F
#define GL_LUMINANCE8 0x8040
#define GL_LUMINANCE12 0x8041
#define GL_LUMINANCE16 0x8042
#define GL_LUMINANCE4_ALPHA4 0x8043
#define GL_LUMINANCE6_ALPHA2 0x8044
#define GL_LUMINANCE8_ALPHA8 0x8045
#define GL_LUMINANCE12_ALPHA4 0x8046
#define GL_LUMINANCE12_ALPHA12 0x8047
#define GL_LUMINANCE16_ALPHA16 0x8048
#define GL_INTENSITY 0x8049
#define GL_INTENSITY4 0x804A
#define GL_INTENSITY8 0x804B
#define GL_INTENSITY12 0x804C
#define GL_INTENSITY16 0x804D
#define GL_R3_G3_B2 0x2A10
#define GL_RGB4 0x804F
#define GL_RGB5 0x8050
#define GL_RGB8 0x8051
#define GL_RGB10 0x8052
#define GL_RGB12 0x8053
#define GL_RGB16 0x8054
#define GL_RGBA2 0x8055
#define GL_RGBA4 0x8056
#define GL_RGB5_A1 0x8057
#define GL_RGBA8 0x8058
#define GL_RGB10_A2 0x8059
#define GL_RGBA12 0x805A
#define GL_RGBA16 0x805B

/* Fog */
#define GL_FOG 0x0B60
#define GL_FOG_MODE 0x0B65
#define GL_FOG_DENSITY 0x0B62
#define GL_FOG_START 0x0B63
#define GL_FOG_END 0x0B64
#define GL_FOG_INDEX 0x0B61
#define GL_FOG_COLOR 0x0B66
#define GL_EXP 0x0800
#define GL_EXP2 0x0801

/* -- Chapter 4: per-fragment operations and the framebuffer -- */

/* Scissor test */
#define GL_SCISSOR_TEST 0x0C11
#define GL_SCISSOR_BOX 0x0C10

/* Alpha test */
#define GL_ALPHA_TEST 0x0BC0
#define GL_ALPHA_TEST_FUNC 0x0BC1
#define GL_ALPHA_TEST_REF 0x0BC2

/* Comparison functions (alpha, stencil, depth) */
#define GL_NEVER 0x0200
#define GL_LESS 0x0201
#define GL_EQUAL 0x0202
#define GL_LEQUAL 0x0203
#define GL_GREATER 0x0204
#define GL_NOTEQUAL 0x0205
#define GL_GEQUAL 0x0206
#define GL_ALWAYS 0x0207

/* Stencil test */
#define GL_STENCIL_TEST 0x0B90
#define GL_STENCIL_FUNC 0x0B92
#define GL_STENCIL_VALUE_MASK 0x0B93
#define GL_STENCIL_REF 0x0B97
#define GL_STENCIL_FAIL 0x0B94
#define GL_STENCIL_PASS_DEPTH_FAIL 0x0B95
#define GL_STENCIL_PASS_DEPTH_PASS 0x0B96
#define GL_STENCIL_WRITEMASK 0x0B98
#define GL_STENCIL_CLEAR_VALUE 0x0B91
#define GL_KEEP 0x1E00
#define GL_REPLACE 0x1E01
#define GL_INCR 0x1E02
#define GL_DECR 0x1E03

/* Depth buffer */
#define GL_DEPTH_TEST 0x0B71
#define GL_DEPTH_FUNC 0x0B74
#define GL_DEPTH_WRITEMASK 0x0B72
#define GL_DEPTH_CLEAR_VALUE 0x0B73

/* Blending */
#define GL_BLEND 0x0BE2
#define GL_BLEND_SRC 0x0BE1
#define GL_BLEND_DST 0x0BE0
#define GL_ZERO 0
#define GL_ONE 1
#define GL_SRC_COLOR 0x0300
#define GL_ONE_MINUS_SRC_COLOR 0x0301
#define GL_DST_COLOR 0x0306
#define GL_ONE_MINUS_DST_COLOR 0x0307
#define GL_SRC_ALPHA 0x0302
#define GL_ONE_MINUS_SRC_ALPHA 0x0303
#define GL_DST_ALPHA 0x0304
#define GL_ONE_MINUS_DST_ALPHA 0x0305
#define GL_SRC_ALPHA_SATURATE 0x0308

/* Dithering */
#define GL_DITHER 0x0BD0

/* Logic operations */
#define GL_LOGIC_OP 0x0BF1
#define GL_INDEX_LOGIC_OP 0x0BF1
#define GL_COLOR_LOGIC_OP 0x0BF2
#define GL_LOGIC_OP_MODE 0x0BF0
#define GL_CLEAR 0x1500
#define GL_AND 0x1501
#define GL_AND_REVERSE 0x1502
#define GL_COPY 0x1503
#define GL_AND_INVERTED 0x1504
#define GL_NOOP 0x1505
#define GL_XOR 0x1506
#define GL_OR 0x1507
#define GL_NOR 0x1508
#define GL_EQUIV 0x1509
#define GL_INVERT 0x150A
#define GL_OR_REVERSE 0x150B
#define GL_COPY_INVERTED 0x150C
#define GL_OR_INVERTED 0x150D
#define GL_NAND 0x150E
#define GL_SET 0x150F

/* Color buffers (glDrawBuffer, glReadBuffer) */
#define GL_NONE 0
#define GL_FRONT_LEFT 0x0400
#define GL_FRONT_RIGHT 0x0401
#define GL_BACK_LEFT 0x0402
#define GL_BACK_RIGHT 0x0403
#define GL_LEFT 0x0406
#define GL_RIGHT 0x0407
#define GL_AUX0 0x0409
#define GL_AUX1 0x040A
#define GL_AUX2 0x040B
#define GL_AUX3 0x040C
#define GL_DRAW_BUFFER 0x0C01
#define GL_READ_BUFFER 0x0C02

/* Write masks and clear values */
#define GL_INDEX_WRITEMASK 0x0C21
#define GL_COLOR_WRITEMASK 0x0C23
#define GL_INDEX_CLEAR_VALUE 0x0C20
#define GL_COLOR_CLEAR_VALUE 0x0C22

/* Accumulation buffer */
#define GL_ACCUM 0x0100
#define GL_LOAD 0x0101
#define GL_RETURN 0x0102
#define GL_MULT 0x0103
#define GL_ADD 0x0104
#define GL_ACCUM_CLEAR_VALUE 0x0B80

/* Framebuffer depths (bits per component) */
#define GL_RED_BITS 0x0D52
#define GL_GREEN_BITS 0x0D53
#define GL_BLUE_BITS 0x0D54
#define GL_ALPHA_BITS 0x0D55
#define GL_INDEX_BITS 0x0D51
#define GL_DEPTH_BITS 0x0D56
#define GL_STENCIL_BITS 0x0D57
#define GL_ACCUM_RED_BITS 0x0D58
#define GL_ACCUM_GREEN_BITS 0x0D59
#define GL_ACCUM_BLUE_BITS 0x0D5A
#define GL_ACCUM_ALPHA_BITS 0x0D5B

/* -- Chapter 5: special functions -- */

/* Evaluators: targets */
#define GL_MAP1_VERTEX_3 0x0D97
#define GL_MAP1_VERTEX_4 0x0D98
#define GL_MAP1_INDEX 0x0D91
#define GL_MAP1_COLOR_4 0x0D90
#define GL_MAP1_NORMAL 0x0D92
#define GL_MAP1_TEXTURE_COORD_1 0x0D93
#define GL_MAP1_TEXTURE_COORD_2 0x0D94
#define GL_MAP1_TEXTURE_COORD_3 0x0D95
#define GL_MAP1_TEXTURE_COORD_4 0x0D96
#define GL_MAP2_VERTEX_3 0x0DB7
#define GL_MAP2_VERTEX_4 0x0DB8
#define GL_MAP2_INDEX 0x0DB1
#define GL_MAP2_COLOR_4 0x0DB0
#define GL_MAP2_NORMAL 0x0DB2
#define GL_MAP2_TEXTURE_COORD_1 0x0DB3
#define GL_MAP2_TEXTURE_COORD_2 0x0DB4
#define GL_MAP2_TEXTURE_COORD_3 0x0DB5
#define GL_MAP2_TEXTURE_COORD_4 0x0DB6

/* Evaluators: grids, glGetMap queries, auto normals */
#define GL_MAP1_GRID_DOMAIN 0x0DD0
#define GL_MAP1_GRID_SEGMENTS 0x0DD1
#define GL_MAP2_GRID_DOMAIN 0x0DD2
#define GL_MAP2_GRID_SEGMENTS 0x0DD3
#define GL_COEFF 0x0A00
#define GL_ORDER 0x0A01
#define GL_DOMAIN 0x0A02
#define GL_AUTO_NORMAL 0x0D80

/* Render modes */
#define GL_RENDER 0x1C00
#define GL_FEEDBACK 0x1C01
#define GL_SELECT 0x1C02
#define GL_RENDER_MODE 0x0C40

/* Selection */
#define GL_SELECTION_BUFFER_POINTER 0x0DF3
#define GL_SELECTION_BUFFER_SIZE 0x0DF4
#define GL_NAME_STACK_DEPTH 0x0D70

/* Feedback: vertex types */
#define GL_2D 0x0600
#define GL_3D 0x0601
#define GL_3D_COLOR 0x0602
#define GL_3D_COLOR_TEXTURE 0x0603
#define GL_4D_COLOR_TEXTURE 0x0604

/* Feedback: buffer tokens */
#define GL_PASS_THROUGH_TOKEN 0x0700
#define GL_POINT_TOKEN 0x0701
#define GL_LINE_TOKEN 0x0702
#define GL_POLYGON_TOKEN 0x0703
#define GL_BITMAP_TOKEN 0x0704
#define GL_DRAW_PIXEL_TOKEN 0x0705
#define GL_COPY_PIXEL_TOKEN 0x0706
#define GL_LINE_RESET_TOKEN 0x0707

/* Feedback: state */
#define GL_FEEDBACK_BUFFER_POINTER 0x0DF0
#define GL_FEEDBACK_BUFFER_SIZE 0x0DF1
#define GL_FEEDBACK_BUFFER_TYPE 0x0DF2

/* Display lists */
#define GL_COMPILE 0x1300
#define GL_COMPILE_AND_EXECUTE 0x1301
#define GL_LIST_BASE 0x0B32
#define GL_LIST_INDEX 0x0B33
#define GL_LIST_MODE 0x0B30

/* Hints */
#define GL_PERSPECTIVE_CORRECTION_HINT 0x0C50
#define GL_POINT_SMOOTH_HINT 0x0C51
#define GL_LINE_SMOOTH_HINT 0x0C52
#define GL_POLYGON_SMOOTH_HINT 0x0C53
#define GL_FOG_HINT 0x0C54
#define GL_DONT_CARE 0x1100
#define GL_FASTEST 0x1101
#define GL_NICEST 0x1102

/* -- Chapter 6: state and state requests -- */

/* glGetString names */
#define GL_VENDOR 0x1F00
#define GL_RENDERER 0x1F01
#define GL_VERSION 0x1F02
#define GL_EXTENSIONS 0x1F03

/* Framebuffer configuration */
#define GL_RGBA_MODE 0x0C31
#define GL_INDEX_MODE 0x0C30
#define GL_DOUBLEBUFFER 0x0C32
#define GL_STEREO 0x0C33
#define GL_AUX_BUFFERS 0x0C00
#define GL_SUBPIXEL_BITS 0x0D50

/* Implementation limits */
#define GL_MAX_LIGHTS 0x0D31
#define GL_MAX_CLIP_PLANES 0x0D32
#define GL_MAX_TEXTURE_SIZE 0x0D33
#define GL_MAX_PIXEL_MAP_TABLE 0x0D34
#define GL_MAX_LIST_NESTING 0x0B31
#define GL_MAX_EVAL_ORDER 0x0D30
#define GL_MAX_VIEWPORT_DIMS 0x0D3A
#define GL_MAX_MODELVIEW_STACK_DEPTH 0x0D36
#define GL_MAX_PROJECTION_STACK_DEPTH 0x0D38
#define GL_MAX_TEXTURE_STACK_DEPTH 0x0D39
#define GL_MAX_NAME_STACK_DEPTH 0x0D37
#define GL_MAX_ATTRIB_STACK_DEPTH 0x0D35
#define GL_MAX_CLIENT_ATTRIB_STACK_DEPTH 0x0D3B

/* Attribute stacks */
#define GL_ATTRIB_STACK_DEPTH 0x0BB0
#define GL_CLIENT_ATTRIB_STACK_DEPTH 0x0BB1

/* glPushAttrib groups (also glClear masks: COLOR, DEPTH, STENCIL, ACCUM) */
#define GL_CURRENT_BIT 0x00000001
#define GL_POINT_BIT 0x00000002
#define GL_LINE_BIT 0x00000004
#define GL_POLYGON_BIT 0x00000008
#define GL_POLYGON_STIPPLE_BIT 0x00000010
#define GL_PIXEL_MODE_BIT 0x00000020
#define GL_LIGHTING_BIT 0x00000040
#define GL_FOG_BIT 0x00000080
#define GL_DEPTH_BUFFER_BIT 0x00000100
#define GL_ACCUM_BUFFER_BIT 0x00000200
#define GL_STENCIL_BUFFER_BIT 0x00000400
#define GL_VIEWPORT_BIT 0x00000800
#define GL_TRANSFORM_BIT 0x00001000
#define GL_ENABLE_BIT 0x00002000
#define GL_COLOR_BUFFER_BIT 0x00004000
#define GL_HINT_BIT 0x00008000
#define GL_EVAL_BIT 0x00010000
#define GL_LIST_BIT 0x00020000
#define GL_TEXTURE_BIT 0x00040000
#define GL_SCISSOR_BIT 0x00080000
#define GL_ALL_ATTRIB_BITS 0xFFFFFFFF

/* glPushClientAttrib groups */
#define GL_CLIENT_PIXEL_STORE_BIT 0x00000001
#define GL_CLIENT_VERTEX_ARRAY_BIT 0x00000002
#define GL_CLIENT_ALL_ATTRIB_BITS 0xFFFFFFFF
#define GL_ALL_CLIENT_ATTRIB_BITS 0xFFFFFFFF

/* ==========================================================================
 * Enumerants, OpenGL 1.2 / 1.3 / 1.4 (the ones course programs use)
 * ========================================================================== */

/* 1.2: texture wrap, LOD and mipmap level range */
#define GL_CLAMP_TO_EDGE 0x812F
#define GL_TEXTURE_MIN_LOD 0x813A
#define GL_TEXTURE_MAX_LOD 0x813B
#define GL_TEXTURE_BASE_LEVEL 0x813C
#define GL_TEXTURE_MAX_LEVEL 0x813D

/* 1.2: lighting */
#define GL_RESCALE_NORMAL 0x803A
#define GL_LIGHT_MODEL_COLOR_CONTROL 0x81F8
#define GL_SINGLE_COLOR 0x81F9
#define GL_SEPARATE_SPECULAR_COLOR 0x81FA

/* 1.2: BGR(A) pixel formats */
#define GL_BGR 0x80E0
#define GL_BGRA 0x80E1

/* 1.2: packed pixel types */
#define GL_UNSIGNED_BYTE_3_3_2 0x8032
#define GL_UNSIGNED_BYTE_2_3_3_REV 0x8362
#define GL_UNSIGNED_SHORT_5_6_5 0x8363
#define GL_UNSIGNED_SHORT_5_6_5_REV 0x8364
#define GL_UNSIGNED_SHORT_4_4_4_4 0x8033
#define GL_UNSIGNED_SHORT_4_4_4_4_REV 0x8365
#define GL_UNSIGNED_SHORT_5_5_5_1 0x8034
#define GL_UNSIGNED_SHORT_1_5_5_5_REV 0x8366
#define GL_UNSIGNED_INT_8_8_8_8 0x8035
#define GL_UNSIGNED_INT_8_8_8_8_REV 0x8367
#define GL_UNSIGNED_INT_10_10_10_2 0x8036
#define GL_UNSIGNED_INT_2_10_10_10_REV 0x8368

/* 1.2: glDrawRangeElements limits */
#define GL_MAX_ELEMENTS_VERTICES 0x80E8
#define GL_MAX_ELEMENTS_INDICES 0x80E9

/* 1.2: point and line size ranges (same values as the 1.1 names) */
#define GL_SMOOTH_POINT_SIZE_RANGE 0x0B12
#define GL_SMOOTH_POINT_SIZE_GRANULARITY 0x0B13
#define GL_SMOOTH_LINE_WIDTH_RANGE 0x0B22
#define GL_SMOOTH_LINE_WIDTH_GRANULARITY 0x0B23
#define GL_ALIASED_POINT_SIZE_RANGE 0x846D
#define GL_ALIASED_LINE_WIDTH_RANGE 0x846E

/* 1.2: 3D texture target (enumerant only; no glTexImage3D here) */
#define GL_TEXTURE_3D 0x806F

/* 1.3: multisampling */
#define GL_MULTISAMPLE 0x809D
#define GL_SAMPLE_BUFFERS 0x80A8
#define GL_SAMPLES 0x80A9

/* 1.3: multitexture units */
#define GL_TEXTURE0 0x84C0
#define GL_TEXTURE1 0x84C1
#define GL_TEXTURE2 0x84C2
#define GL_TEXTURE3 0x84C3
#define GL_TEXTURE4 0x84C4
#define GL_TEXTURE5 0x84C5
#define GL_TEXTURE6 0x84C6
#define GL_TEXTURE7 0x84C7
#define GL_TEXTURE8 0x84C8
#define GL_TEXTURE9 0x84C9
#define GL_TEXTURE10 0x84CA
#define GL_TEXTURE11 0x84CB
#define GL_TEXTURE12 0x84CC
#define GL_TEXTURE13 0x84CD
#define GL_TEXTURE14 0x84CE
#define GL_TEXTURE15 0x84CF
#define GL_TEXTURE16 0x84D0
#define GL_TEXTURE17 0x84D1
#define GL_TEXTURE18 0x84D2
#define GL_TEXTURE19 0x84D3
#define GL_TEXTURE20 0x84D4
#define GL_TEXTURE21 0x84D5
#define GL_TEXTURE22 0x84D6
#define GL_TEXTURE23 0x84D7
#define GL_TEXTURE24 0x84D8
#define GL_TEXTURE25 0x84D9
#define GL_TEXTURE26 0x84DA
#define GL_TEXTURE27 0x84DB
#define GL_TEXTURE28 0x84DC
#define GL_TEXTURE29 0x84DD
#define GL_TEXTURE30 0x84DE
#define GL_TEXTURE31 0x84DF
#define GL_ACTIVE_TEXTURE 0x84E0
#define GL_CLIENT_ACTIVE_TEXTURE 0x84E1
#define GL_MAX_TEXTURE_UNITS 0x84E2

/* 1.4: automatic mipmap generation (glTexParameter) and its hint */
#define GL_GENERATE_MIPMAP 0x8191
#define GL_GENERATE_MIPMAP_HINT 0x8192

/* ==========================================================================
 * Entry points, OpenGL 1.1 (grouped after the chapters of the 1.1 spec)
 * ========================================================================== */

/* Errors (2.5) */
TESSEL_GLAPI GLenum TESSEL_APIENTRY glGetError(void);

/* Begin/End and edge flags (2.6) */
TESSEL_GLAPI void TESSEL_APIENTRY glBegin(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glEnd(void);
TESSEL_GLAPI void TESSEL_APIENTRY glEdgeFlag(GLboolean flag);
TESSEL_GLAPI void TESSEL_APIENTRY glEdgeFlagv(const GLboolean* flag);

/* Vertices (2.7): glVertex{234}{sifd}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2d(GLdouble x, GLdouble y);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2f(GLfloat x, GLfloat y);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2i(GLint x, GLint y);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2s(GLshort x, GLshort y);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex2sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3d(GLdouble x, GLdouble y, GLdouble z);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3f(GLfloat x, GLfloat y, GLfloat z);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3i(GLint x, GLint y, GLint z);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3s(GLshort x, GLshort y, GLshort z);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex3sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4i(GLint x, GLint y, GLint z, GLint w);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4s(GLshort x, GLshort y, GLshort z, GLshort w);
TESSEL_GLAPI void TESSEL_APIENTRY glVertex4sv(const GLshort* v);

/* Texture coordinates (2.7): glTexCoord{1234}{sifd}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1d(GLdouble s);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1f(GLfloat s);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1i(GLint s);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1s(GLshort s);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord1sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2d(GLdouble s, GLdouble t);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2f(GLfloat s, GLfloat t);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2i(GLint s, GLint t);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2s(GLshort s, GLshort t);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord2sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3d(GLdouble s, GLdouble t, GLdouble r);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3f(GLfloat s, GLfloat t, GLfloat r);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3i(GLint s, GLint t, GLint r);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3s(GLshort s, GLshort t, GLshort r);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord3sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4d(GLdouble s, GLdouble t, GLdouble r, GLdouble q);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4i(GLint s, GLint t, GLint r, GLint q);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4s(GLshort s, GLshort t, GLshort r, GLshort q);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoord4sv(const GLshort* v);

/* Normals (2.7): glNormal3{bsifd}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3b(GLbyte nx, GLbyte ny, GLbyte nz);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3bv(const GLbyte* v);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3d(GLdouble nx, GLdouble ny, GLdouble nz);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3f(GLfloat nx, GLfloat ny, GLfloat nz);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3i(GLint nx, GLint ny, GLint nz);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3s(GLshort nx, GLshort ny, GLshort nz);
TESSEL_GLAPI void TESSEL_APIENTRY glNormal3sv(const GLshort* v);

/* Colors (2.7): glColor{34}{b,s,i,f,d,ub,us,ui}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glColor3b(GLbyte red, GLbyte green, GLbyte blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3bv(const GLbyte* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3d(GLdouble red, GLdouble green, GLdouble blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3f(GLfloat red, GLfloat green, GLfloat blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3i(GLint red, GLint green, GLint blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3s(GLshort red, GLshort green, GLshort blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3ub(GLubyte red, GLubyte green, GLubyte blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3ubv(const GLubyte* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3ui(GLuint red, GLuint green, GLuint blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3uiv(const GLuint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3us(GLushort red, GLushort green, GLushort blue);
TESSEL_GLAPI void TESSEL_APIENTRY glColor3usv(const GLushort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4b(GLbyte red, GLbyte green, GLbyte blue, GLbyte alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4bv(const GLbyte* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4d(GLdouble red, GLdouble green, GLdouble blue, GLdouble alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4f(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4i(GLint red, GLint green, GLint blue, GLint alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4s(GLshort red, GLshort green, GLshort blue, GLshort alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4ub(GLubyte red, GLubyte green, GLubyte blue, GLubyte alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4ubv(const GLubyte* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4ui(GLuint red, GLuint green, GLuint blue, GLuint alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4uiv(const GLuint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4us(GLushort red, GLushort green, GLushort blue, GLushort alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glColor4usv(const GLushort* v);

/* Color indices (2.7): glIndex{s,i,f,d,ub}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glIndexd(GLdouble c);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexdv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexf(GLfloat c);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexfv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexi(GLint c);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexiv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexs(GLshort c);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexsv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexub(GLubyte c);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexubv(const GLubyte* v);

/* Vertex arrays (2.8) */
TESSEL_GLAPI void TESSEL_APIENTRY glVertexPointer(GLint size, GLenum type, GLsizei stride,
                                                  const GLvoid* pointer);
TESSEL_GLAPI void TESSEL_APIENTRY glNormalPointer(GLenum type, GLsizei stride, const GLvoid* pointer);
TESSEL_GLAPI void TESSEL_APIENTRY glColorPointer(GLint size, GLenum type, GLsizei stride,
                                                 const GLvoid* pointer);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexPointer(GLenum type, GLsizei stride, const GLvoid* pointer);
TESSEL_GLAPI void TESSEL_APIENTRY glTexCoordPointer(GLint size, GLenum type, GLsizei stride,
                                                    const GLvoid* pointer);
TESSEL_GLAPI void TESSEL_APIENTRY glEdgeFlagPointer(GLsizei stride, const GLvoid* pointer);
TESSEL_GLAPI void TESSEL_APIENTRY glEnableClientState(GLenum array);
TESSEL_GLAPI void TESSEL_APIENTRY glDisableClientState(GLenum array);
TESSEL_GLAPI void TESSEL_APIENTRY glArrayElement(GLint i);
TESSEL_GLAPI void TESSEL_APIENTRY glDrawArrays(GLenum mode, GLint first, GLsizei count);
TESSEL_GLAPI void TESSEL_APIENTRY glDrawElements(GLenum mode, GLsizei count, GLenum type,
                                                 const GLvoid* indices);
TESSEL_GLAPI void TESSEL_APIENTRY glInterleavedArrays(GLenum format, GLsizei stride, const GLvoid* pointer);

/* Rectangles (2.9): glRect{sifd}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2);
TESSEL_GLAPI void TESSEL_APIENTRY glRectdv(const GLdouble* v1, const GLdouble* v2);
TESSEL_GLAPI void TESSEL_APIENTRY glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2);
TESSEL_GLAPI void TESSEL_APIENTRY glRectfv(const GLfloat* v1, const GLfloat* v2);
TESSEL_GLAPI void TESSEL_APIENTRY glRecti(GLint x1, GLint y1, GLint x2, GLint y2);
TESSEL_GLAPI void TESSEL_APIENTRY glRectiv(const GLint* v1, const GLint* v2);
TESSEL_GLAPI void TESSEL_APIENTRY glRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2);
TESSEL_GLAPI void TESSEL_APIENTRY glRectsv(const GLshort* v1, const GLshort* v2);

/* Coordinate transformations (2.10) */
TESSEL_GLAPI void TESSEL_APIENTRY glDepthRange(GLclampd zNear, GLclampd zFar);
TESSEL_GLAPI void TESSEL_APIENTRY glViewport(GLint x, GLint y, GLsizei width, GLsizei height);
TESSEL_GLAPI void TESSEL_APIENTRY glMatrixMode(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glLoadMatrixd(const GLdouble* m);
TESSEL_GLAPI void TESSEL_APIENTRY glLoadMatrixf(const GLfloat* m);
TESSEL_GLAPI void TESSEL_APIENTRY glMultMatrixd(const GLdouble* m);
TESSEL_GLAPI void TESSEL_APIENTRY glMultMatrixf(const GLfloat* m);
TESSEL_GLAPI void TESSEL_APIENTRY glLoadIdentity(void);
TESSEL_GLAPI void TESSEL_APIENTRY glRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z);
TESSEL_GLAPI void TESSEL_APIENTRY glRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z);
TESSEL_GLAPI void TESSEL_APIENTRY glTranslated(GLdouble x, GLdouble y, GLdouble z);
TESSEL_GLAPI void TESSEL_APIENTRY glTranslatef(GLfloat x, GLfloat y, GLfloat z);
TESSEL_GLAPI void TESSEL_APIENTRY glScaled(GLdouble x, GLdouble y, GLdouble z);
TESSEL_GLAPI void TESSEL_APIENTRY glScalef(GLfloat x, GLfloat y, GLfloat z);
TESSEL_GLAPI void TESSEL_APIENTRY glFrustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top,
                                            GLdouble zNear, GLdouble zFar);
TESSEL_GLAPI void TESSEL_APIENTRY glOrtho(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top,
                                          GLdouble zNear, GLdouble zFar);
TESSEL_GLAPI void TESSEL_APIENTRY glPushMatrix(void);
TESSEL_GLAPI void TESSEL_APIENTRY glPopMatrix(void);

/* Texture coordinate generation (2.10.4) */
TESSEL_GLAPI void TESSEL_APIENTRY glTexGend(GLenum coord, GLenum pname, GLdouble param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexGendv(GLenum coord, GLenum pname, const GLdouble* params);
TESSEL_GLAPI void TESSEL_APIENTRY glTexGenf(GLenum coord, GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexGenfv(GLenum coord, GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glTexGeni(GLenum coord, GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexGeniv(GLenum coord, GLenum pname, const GLint* params);

/* Clipping (2.11) */
TESSEL_GLAPI void TESSEL_APIENTRY glClipPlane(GLenum plane, const GLdouble* equation);

/* Raster position (2.12): glRasterPos{234}{sifd}[v] */
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2d(GLdouble x, GLdouble y);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2f(GLfloat x, GLfloat y);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2i(GLint x, GLint y);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2s(GLshort x, GLshort y);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos2sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3d(GLdouble x, GLdouble y, GLdouble z);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3f(GLfloat x, GLfloat y, GLfloat z);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3i(GLint x, GLint y, GLint z);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3s(GLshort x, GLshort y, GLshort z);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos3sv(const GLshort* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4dv(const GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4fv(const GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4i(GLint x, GLint y, GLint z, GLint w);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4iv(const GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w);
TESSEL_GLAPI void TESSEL_APIENTRY glRasterPos4sv(const GLshort* v);

/* Lighting and shading (2.13) */
TESSEL_GLAPI void TESSEL_APIENTRY glFrontFace(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glMaterialf(GLenum face, GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glMaterialfv(GLenum face, GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glMateriali(GLenum face, GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glMaterialiv(GLenum face, GLenum pname, const GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glLightf(GLenum light, GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glLightfv(GLenum light, GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glLighti(GLenum light, GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glLightiv(GLenum light, GLenum pname, const GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glLightModelf(GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glLightModelfv(GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glLightModeli(GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glLightModeliv(GLenum pname, const GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glColorMaterial(GLenum face, GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glShadeModel(GLenum mode);

/* Points, lines, polygons (3.3 - 3.5) */
TESSEL_GLAPI void TESSEL_APIENTRY glPointSize(GLfloat size);
TESSEL_GLAPI void TESSEL_APIENTRY glLineWidth(GLfloat width);
TESSEL_GLAPI void TESSEL_APIENTRY glLineStipple(GLint factor, GLushort pattern);
TESSEL_GLAPI void TESSEL_APIENTRY glCullFace(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glPolygonStipple(const GLubyte* mask);
TESSEL_GLAPI void TESSEL_APIENTRY glPolygonMode(GLenum face, GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glPolygonOffset(GLfloat factor, GLfloat units);

/* Pixel storage, transfer and maps (3.6.1 - 3.6.3) */
TESSEL_GLAPI void TESSEL_APIENTRY glPixelStoref(GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelStorei(GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelTransferf(GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelTransferi(GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat* values);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint* values);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelMapusv(GLenum map, GLsizei mapsize, const GLushort* values);

/* Pixel rectangles and bitmaps (3.6.4, 3.7, 4.3) */
TESSEL_GLAPI void TESSEL_APIENTRY glDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                                               const GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glPixelZoom(GLfloat xfactor, GLfloat yfactor);
TESSEL_GLAPI void TESSEL_APIENTRY glBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
                                           GLfloat xmove, GLfloat ymove, const GLubyte* bitmap);
TESSEL_GLAPI void TESSEL_APIENTRY glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                                               GLenum type, GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glReadBuffer(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type);

/* Texture images (3.8.1 - 3.8.2) */
TESSEL_GLAPI void TESSEL_APIENTRY glTexImage1D(GLenum target, GLint level, GLint internalFormat,
                                               GLsizei width, GLint border, GLenum format, GLenum type,
                                               const GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glTexImage2D(GLenum target, GLint level, GLint internalFormat,
                                               GLsizei width, GLsizei height, GLint border, GLenum format,
                                               GLenum type, const GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glCopyTexImage1D(GLenum target, GLint level, GLenum internalFormat, GLint x,
                                                   GLint y, GLsizei width, GLint border);
TESSEL_GLAPI void TESSEL_APIENTRY glCopyTexImage2D(GLenum target, GLint level, GLenum internalFormat, GLint x,
                                                   GLint y, GLsizei width, GLsizei height, GLint border);
TESSEL_GLAPI void TESSEL_APIENTRY glTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                                                  GLenum format, GLenum type, const GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                                  GLsizei width, GLsizei height, GLenum format, GLenum type,
                                                  const GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x,
                                                      GLint y, GLsizei width);
TESSEL_GLAPI void TESSEL_APIENTRY glCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset,
                                                      GLint yoffset, GLint x, GLint y, GLsizei width,
                                                      GLsizei height);

/* Texture parameters, objects and environment (3.8.3 - 3.8.9) */
TESSEL_GLAPI void TESSEL_APIENTRY glTexParameterf(GLenum target, GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexParameterfv(GLenum target, GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glTexParameteri(GLenum target, GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexParameteriv(GLenum target, GLenum pname, const GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGenTextures(GLsizei n, GLuint* textures);
TESSEL_GLAPI void TESSEL_APIENTRY glDeleteTextures(GLsizei n, const GLuint* textures);
TESSEL_GLAPI void TESSEL_APIENTRY glBindTexture(GLenum target, GLuint texture);
TESSEL_GLAPI GLboolean TESSEL_APIENTRY glIsTexture(GLuint texture);
TESSEL_GLAPI void TESSEL_APIENTRY glPrioritizeTextures(GLsizei n, const GLuint* textures,
                                                       const GLclampf* priorities);
TESSEL_GLAPI GLboolean TESSEL_APIENTRY glAreTexturesResident(GLsizei n, const GLuint* textures,
                                                             GLboolean* residences);
TESSEL_GLAPI void TESSEL_APIENTRY glTexEnvf(GLenum target, GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexEnvfv(GLenum target, GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glTexEnvi(GLenum target, GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glTexEnviv(GLenum target, GLenum pname, const GLint* params);

/* Fog (3.9) */
TESSEL_GLAPI void TESSEL_APIENTRY glFogf(GLenum pname, GLfloat param);
TESSEL_GLAPI void TESSEL_APIENTRY glFogfv(GLenum pname, const GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glFogi(GLenum pname, GLint param);
TESSEL_GLAPI void TESSEL_APIENTRY glFogiv(GLenum pname, const GLint* params);

/* Per-fragment operations (4.1) */
TESSEL_GLAPI void TESSEL_APIENTRY glScissor(GLint x, GLint y, GLsizei width, GLsizei height);
TESSEL_GLAPI void TESSEL_APIENTRY glAlphaFunc(GLenum func, GLclampf ref);
TESSEL_GLAPI void TESSEL_APIENTRY glStencilFunc(GLenum func, GLint ref, GLuint mask);
TESSEL_GLAPI void TESSEL_APIENTRY glStencilOp(GLenum fail, GLenum zfail, GLenum zpass);
TESSEL_GLAPI void TESSEL_APIENTRY glDepthFunc(GLenum func);
TESSEL_GLAPI void TESSEL_APIENTRY glBlendFunc(GLenum sfactor, GLenum dfactor);
TESSEL_GLAPI void TESSEL_APIENTRY glLogicOp(GLenum opcode);

/* Framebuffer control, clears and the accumulation buffer (4.2) */
TESSEL_GLAPI void TESSEL_APIENTRY glDrawBuffer(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glIndexMask(GLuint mask);
TESSEL_GLAPI void TESSEL_APIENTRY glColorMask(GLboolean red, GLboolean green, GLboolean blue,
                                              GLboolean alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glDepthMask(GLboolean flag);
TESSEL_GLAPI void TESSEL_APIENTRY glStencilMask(GLuint mask);
TESSEL_GLAPI void TESSEL_APIENTRY glClear(GLbitfield mask);
TESSEL_GLAPI void TESSEL_APIENTRY glClearColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glClearIndex(GLfloat c);
TESSEL_GLAPI void TESSEL_APIENTRY glClearDepth(GLclampd depth);
TESSEL_GLAPI void TESSEL_APIENTRY glClearStencil(GLint s);
TESSEL_GLAPI void TESSEL_APIENTRY glClearAccum(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha);
TESSEL_GLAPI void TESSEL_APIENTRY glAccum(GLenum op, GLfloat value);

/* Evaluators (5.1) */
TESSEL_GLAPI void TESSEL_APIENTRY glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                                          const GLdouble* points);
TESSEL_GLAPI void TESSEL_APIENTRY glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                                          const GLfloat* points);
TESSEL_GLAPI void TESSEL_APIENTRY glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride,
                                          GLint uorder, GLdouble v1, GLdouble v2, GLint vstride, GLint vorder,
                                          const GLdouble* points);
TESSEL_GLAPI void TESSEL_APIENTRY glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                                          GLfloat v1, GLfloat v2, GLint vstride, GLint vorder,
                                          const GLfloat* points);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord1d(GLdouble u);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord1dv(const GLdouble* u);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord2d(GLdouble u, GLdouble v);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord2dv(const GLdouble* u);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord1f(GLfloat u);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord1fv(const GLfloat* u);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord2f(GLfloat u, GLfloat v);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalCoord2fv(const GLfloat* u);
TESSEL_GLAPI void TESSEL_APIENTRY glMapGrid1d(GLint un, GLdouble u1, GLdouble u2);
TESSEL_GLAPI void TESSEL_APIENTRY glMapGrid1f(GLint un, GLfloat u1, GLfloat u2);
TESSEL_GLAPI void TESSEL_APIENTRY glMapGrid2d(GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1,
                                              GLdouble v2);
TESSEL_GLAPI void TESSEL_APIENTRY glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1,
                                              GLfloat v2);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalMesh1(GLenum mode, GLint i1, GLint i2);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalPoint1(GLint i);
TESSEL_GLAPI void TESSEL_APIENTRY glEvalPoint2(GLint i, GLint j);

/* Selection and feedback (5.2 - 5.3) */
TESSEL_GLAPI GLint TESSEL_APIENTRY glRenderMode(GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glSelectBuffer(GLsizei size, GLuint* buffer);
TESSEL_GLAPI void TESSEL_APIENTRY glInitNames(void);
TESSEL_GLAPI void TESSEL_APIENTRY glPushName(GLuint name);
TESSEL_GLAPI void TESSEL_APIENTRY glPopName(void);
TESSEL_GLAPI void TESSEL_APIENTRY glLoadName(GLuint name);
TESSEL_GLAPI void TESSEL_APIENTRY glFeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer);
TESSEL_GLAPI void TESSEL_APIENTRY glPassThrough(GLfloat token);

/* Display lists (5.4) */
TESSEL_GLAPI void TESSEL_APIENTRY glNewList(GLuint list, GLenum mode);
TESSEL_GLAPI void TESSEL_APIENTRY glEndList(void);
TESSEL_GLAPI void TESSEL_APIENTRY glCallList(GLuint list);
TESSEL_GLAPI void TESSEL_APIENTRY glCallLists(GLsizei n, GLenum type, const GLvoid* lists);
TESSEL_GLAPI void TESSEL_APIENTRY glListBase(GLuint base);
TESSEL_GLAPI GLuint TESSEL_APIENTRY glGenLists(GLsizei range);
TESSEL_GLAPI GLboolean TESSEL_APIENTRY glIsList(GLuint list);
TESSEL_GLAPI void TESSEL_APIENTRY glDeleteLists(GLuint list, GLsizei range);

/* Flush, finish and hints (5.5 - 5.6) */
TESSEL_GLAPI void TESSEL_APIENTRY glFlush(void);
TESSEL_GLAPI void TESSEL_APIENTRY glFinish(void);
TESSEL_GLAPI void TESSEL_APIENTRY glHint(GLenum target, GLenum mode);

/* Capabilities (2.11 and throughout) */
TESSEL_GLAPI void TESSEL_APIENTRY glEnable(GLenum cap);
TESSEL_GLAPI void TESSEL_APIENTRY glDisable(GLenum cap);
TESSEL_GLAPI GLboolean TESSEL_APIENTRY glIsEnabled(GLenum cap);

/* Simple state queries (6.1.1 - 6.1.2) */
TESSEL_GLAPI void TESSEL_APIENTRY glGetBooleanv(GLenum pname, GLboolean* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetIntegerv(GLenum pname, GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetFloatv(GLenum pname, GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetDoublev(GLenum pname, GLdouble* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetPointerv(GLenum pname, GLvoid** params);
TESSEL_GLAPI const GLubyte* TESSEL_APIENTRY glGetString(GLenum name);

/* Object state queries (6.1.3 - 6.1.11) */
TESSEL_GLAPI void TESSEL_APIENTRY glGetClipPlane(GLenum plane, GLdouble* equation);
TESSEL_GLAPI void TESSEL_APIENTRY glGetLightfv(GLenum light, GLenum pname, GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetLightiv(GLenum light, GLenum pname, GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetMaterialfv(GLenum face, GLenum pname, GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetMaterialiv(GLenum face, GLenum pname, GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexEnvfv(GLenum target, GLenum pname, GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexEnviv(GLenum target, GLenum pname, GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexGendv(GLenum coord, GLenum pname, GLdouble* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexGenfv(GLenum coord, GLenum pname, GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexGeniv(GLenum coord, GLenum pname, GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexParameterfv(GLenum target, GLenum pname, GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexParameteriv(GLenum target, GLenum pname, GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname,
                                                           GLfloat* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname,
                                                           GLint* params);
TESSEL_GLAPI void TESSEL_APIENTRY glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type,
                                                GLvoid* pixels);
TESSEL_GLAPI void TESSEL_APIENTRY glGetPixelMapfv(GLenum map, GLfloat* values);
TESSEL_GLAPI void TESSEL_APIENTRY glGetPixelMapuiv(GLenum map, GLuint* values);
TESSEL_GLAPI void TESSEL_APIENTRY glGetPixelMapusv(GLenum map, GLushort* values);
TESSEL_GLAPI void TESSEL_APIENTRY glGetMapdv(GLenum target, GLenum query, GLdouble* v);
TESSEL_GLAPI void TESSEL_APIENTRY glGetMapfv(GLenum target, GLenum query, GLfloat* v);
TESSEL_GLAPI void TESSEL_APIENTRY glGetMapiv(GLenum target, GLenum query, GLint* v);
TESSEL_GLAPI void TESSEL_APIENTRY glGetPolygonStipple(GLubyte* mask);

/* Attribute stacks (6.1.12) */
TESSEL_GLAPI void TESSEL_APIENTRY glPushAttrib(GLbitfield mask);
TESSEL_GLAPI void TESSEL_APIENTRY glPopAttrib(void);
TESSEL_GLAPI void TESSEL_APIENTRY glPushClientAttrib(GLbitfield mask);
TESSEL_GLAPI void TESSEL_APIENTRY glPopClientAttrib(void);

/* ==========================================================================
 * Entry points, OpenGL 1.2 / 1.3 (a subset)
 * ========================================================================== */

/* 1.2: indexed drawing with a declared index range */
TESSEL_GLAPI void TESSEL_APIENTRY glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                                      GLenum type, const GLvoid* indices);

/* 1.3: multitexture (texture unit selection and per-unit coordinates) */
TESSEL_GLAPI void TESSEL_APIENTRY glActiveTexture(GLenum texture);
TESSEL_GLAPI void TESSEL_APIENTRY glClientActiveTexture(GLenum texture);
TESSEL_GLAPI void TESSEL_APIENTRY glMultiTexCoord2f(GLenum target, GLfloat s, GLfloat t);
TESSEL_GLAPI void TESSEL_APIENTRY glMultiTexCoord2fv(GLenum target, const GLfloat* v);

#ifdef __cplusplus
} /* extern "C" */
#endif

/* What GL 1.2 to 3.3 add (prototypes with GL_GLEXT_PROTOTYPES), as Mesa's gl.h does. */
#ifndef GL_GLEXT_LEGACY
#include <GL/glext.h>
#endif

#endif /* TESSEL_COMPAT_GL_GL_H */
