/*
 * Tessel compatibility header: <GL/glut.h>
 *
 * Declares the GLUT 3.7 API (GLUT_API_VERSION 4) and the freeglut additions
 * that course programs commonly use (glutLeaveMainLoop, glutMainLoopEvent,
 * glutSetOption, glutCloseFunc, glutMouseWheelFunc, glutBitmapString, ...).
 * Tessel provides the definitions in its own libraries; this file only
 * declares them.  Written for Tessel; the names and numbers are those of the
 * GLUT 3.7 specification and of freeglut.
 *
 * Usable from C (C89/C99 and later) and from C++.  Callback parameters are
 * plain function pointers with C language linkage.
 */
#if !defined(TESSEL_COMPAT_GL_GLUT_H) && !defined(__glut_h__) && !defined(__GLUT_H__)
#define TESSEL_COMPAT_GL_GLUT_H 1
/* The traditional guards, so that another glut.h included later is skipped. */
#define __glut_h__ 1
#define __GLUT_H__ 1

/* stdlib.h: GLUT programs customarily end themselves from their own keyboard and menu
   callbacks with stdlib's exit without including stdlib.h, relying on glut.h (SGI's and
   freeglut's include it). Tessel itself never ends the program: GLUT errors are reported on
   stderr and glutMainLoop returns. */
#include <stdlib.h>

#include <GL/gl.h>
#include <GL/glu.h>

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

/* freeglut's export macros, so that freeglut's own extension headers can
 * still be included after this one. */
#ifndef FGAPI
#define FGAPI TESSEL_GLAPI
#endif
#ifndef FGAPIENTRY
#define FGAPIENTRY TESSEL_APIENTRY
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define GLUT_API_VERSION 4

/* ---- glutInitDisplayMode bits -------------------------------------------- */
/* RGBA and single buffering are the defaults and have the value 0. */
#define GLUT_RGB 0x0000
#define GLUT_RGBA 0x0000
#define GLUT_INDEX 0x0001
#define GLUT_SINGLE 0x0000
#define GLUT_DOUBLE 0x0002
#define GLUT_ACCUM 0x0004
#define GLUT_ALPHA 0x0008
#define GLUT_DEPTH 0x0010
#define GLUT_STENCIL 0x0020
#define GLUT_MULTISAMPLE 0x0080
#define GLUT_STEREO 0x0100
#define GLUT_LUMINANCE 0x0200

/* ---- Mouse (glutMouseFunc) and entry (glutEntryFunc) --------------------- */
#define GLUT_LEFT_BUTTON 0x0000
#define GLUT_MIDDLE_BUTTON 0x0001
#define GLUT_RIGHT_BUTTON 0x0002
#define GLUT_DOWN 0x0000
#define GLUT_UP 0x0001
#define GLUT_LEFT 0x0000
#define GLUT_ENTERED 0x0001

/* ---- Special keys (glutSpecialFunc) -------------------------------------- */
#define GLUT_KEY_F1 0x0001
#define GLUT_KEY_F2 0x0002
#define GLUT_KEY_F3 0x0003
#define GLUT_KEY_F4 0x0004
#define GLUT_KEY_F5 0x0005
#define GLUT_KEY_F6 0x0006
#define GLUT_KEY_F7 0x0007
#define GLUT_KEY_F8 0x0008
#define GLUT_KEY_F9 0x0009
#define GLUT_KEY_F10 0x000A
#define GLUT_KEY_F11 0x000B
#define GLUT_KEY_F12 0x000C
#define GLUT_KEY_LEFT 0x0064
#define GLUT_KEY_UP 0x0065
#define GLUT_KEY_RIGHT 0x0066
#define GLUT_KEY_DOWN 0x0067
#define GLUT_KEY_PAGE_UP 0x0068
#define GLUT_KEY_PAGE_DOWN 0x0069
#define GLUT_KEY_HOME 0x006A
#define GLUT_KEY_END 0x006B
#define GLUT_KEY_INSERT 0x006C
/* freeglut additions */
#define GLUT_KEY_NUM_LOCK 0x006D
#define GLUT_KEY_BEGIN 0x006E
#define GLUT_KEY_DELETE 0x006F
#define GLUT_KEY_SHIFT_L 0x0070
#define GLUT_KEY_SHIFT_R 0x0071
#define GLUT_KEY_CTRL_L 0x0072
#define GLUT_KEY_CTRL_R 0x0073
#define GLUT_KEY_ALT_L 0x0074
#define GLUT_KEY_ALT_R 0x0075
#define GLUT_KEY_SUPER_L 0x0076
#define GLUT_KEY_SUPER_R 0x0077

/* ---- Modifier mask (glutGetModifiers) ------------------------------------ */
#define GLUT_ACTIVE_SHIFT 0x0001
#define GLUT_ACTIVE_CTRL 0x0002
#define GLUT_ACTIVE_ALT 0x0004
#define GLUT_ACTIVE_SUPER 0x0008 /* freeglut */

/* ---- Visibility, window status and menu status --------------------------- */
#define GLUT_NOT_VISIBLE 0x0000
#define GLUT_VISIBLE 0x0001
#define GLUT_HIDDEN 0x0000
#define GLUT_FULLY_RETAINED 0x0001
#define GLUT_PARTIALLY_RETAINED 0x0002
#define GLUT_FULLY_COVERED 0x0003
#define GLUT_MENU_NOT_IN_USE 0x0000
#define GLUT_MENU_IN_USE 0x0001

/* ---- Fonts --------------------------------------------------------------- */
/* Font handles are small distinct integers disguised as pointers; they are
 * only ever compared, never dereferenced.  Stroke fonts first. */
#define GLUT_STROKE_ROMAN ((void*)0x0000)
#define GLUT_STROKE_MONO_ROMAN ((void*)0x0001)
#define GLUT_BITMAP_9_BY_15 ((void*)0x0002)
#define GLUT_BITMAP_8_BY_13 ((void*)0x0003)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void*)0x0004)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void*)0x0005)
#define GLUT_BITMAP_HELVETICA_10 ((void*)0x0006)
#define GLUT_BITMAP_HELVETICA_12 ((void*)0x0007)
#define GLUT_BITMAP_HELVETICA_18 ((void*)0x0008)

/* ---- glutGet queries ----------------------------------------------------- */
/* Current window: geometry and framebuffer configuration */
#define GLUT_WINDOW_X 0x0064
#define GLUT_WINDOW_Y 0x0065
#define GLUT_WINDOW_WIDTH 0x0066
#define GLUT_WINDOW_HEIGHT 0x0067
#define GLUT_WINDOW_BUFFER_SIZE 0x0068
#define GLUT_WINDOW_STENCIL_SIZE 0x0069
#define GLUT_WINDOW_DEPTH_SIZE 0x006A
#define GLUT_WINDOW_RED_SIZE 0x006B
#define GLUT_WINDOW_GREEN_SIZE 0x006C
#define GLUT_WINDOW_BLUE_SIZE 0x006D
#define GLUT_WINDOW_ALPHA_SIZE 0x006E
#define GLUT_WINDOW_ACCUM_RED_SIZE 0x006F
#define GLUT_WINDOW_ACCUM_GREEN_SIZE 0x0070
#define GLUT_WINDOW_ACCUM_BLUE_SIZE 0x0071
#define GLUT_WINDOW_ACCUM_ALPHA_SIZE 0x0072
#define GLUT_WINDOW_DOUBLEBUFFER 0x0073
#define GLUT_WINDOW_RGBA 0x0074
#define GLUT_WINDOW_PARENT 0x0075
#define GLUT_WINDOW_NUM_CHILDREN 0x0076
#define GLUT_WINDOW_COLORMAP_SIZE 0x0077
#define GLUT_WINDOW_NUM_SAMPLES 0x0078
#define GLUT_WINDOW_STEREO 0x0079
#define GLUT_WINDOW_CURSOR 0x007A
#define GLUT_WINDOW_FORMAT_ID 0x007B
/* Screen */
#define GLUT_SCREEN_WIDTH 0x00C8
#define GLUT_SCREEN_HEIGHT 0x00C9
#define GLUT_SCREEN_WIDTH_MM 0x00CA
#define GLUT_SCREEN_HEIGHT_MM 0x00CB
/* Menus, display modes, initial state, time */
#define GLUT_MENU_NUM_ITEMS 0x012C
#define GLUT_DISPLAY_MODE_POSSIBLE 0x0190
#define GLUT_INIT_WINDOW_X 0x01F4
#define GLUT_INIT_WINDOW_Y 0x01F5
#define GLUT_INIT_WINDOW_WIDTH 0x01F6
#define GLUT_INIT_WINDOW_HEIGHT 0x01F7
#define GLUT_INIT_DISPLAY_MODE 0x01F8
#define GLUT_ELAPSED_TIME 0x02BC
/* freeglut additions (glutGet, and glutSetOption where settable) */
#define GLUT_INIT_STATE 0x007C
#define GLUT_ACTION_ON_WINDOW_CLOSE 0x01F9
#define GLUT_WINDOW_BORDER_WIDTH 0x01FA
#define GLUT_WINDOW_BORDER_HEIGHT 0x01FB
#define GLUT_WINDOW_HEADER_HEIGHT 0x01FB
#define GLUT_VERSION 0x01FC
#define GLUT_RENDERING_CONTEXT 0x01FD
#define GLUT_DIRECT_RENDERING 0x01FE
#define GLUT_FULL_SCREEN 0x01FF
#define GLUT_SKIP_STALE_MOTION_EVENTS 0x0204

/* Values of GLUT_ACTION_ON_WINDOW_CLOSE (freeglut) */
#define GLUT_ACTION_EXIT 0
#define GLUT_ACTION_GLUTMAINLOOP_RETURNS 1
#define GLUT_ACTION_CONTINUE_EXECUTION 2

/* Values of GLUT_RENDERING_CONTEXT (freeglut) */
#define GLUT_CREATE_NEW_CONTEXT 0
#define GLUT_USE_CURRENT_CONTEXT 1

/* ---- glutDeviceGet queries ----------------------------------------------- */
#define GLUT_HAS_KEYBOARD 0x0258
#define GLUT_HAS_MOUSE 0x0259
#define GLUT_HAS_SPACEBALL 0x025A
#define GLUT_HAS_DIAL_AND_BUTTON_BOX 0x025B
#define GLUT_HAS_TABLET 0x025C
#define GLUT_NUM_MOUSE_BUTTONS 0x025D
#define GLUT_NUM_SPACEBALL_BUTTONS 0x025E
#define GLUT_NUM_BUTTON_BOX_BUTTONS 0x025F
#define GLUT_NUM_DIALS 0x0260
#define GLUT_NUM_TABLET_BUTTONS 0x0261
#define GLUT_DEVICE_IGNORE_KEY_REPEAT 0x0262
#define GLUT_DEVICE_KEY_REPEAT 0x0263
#define GLUT_HAS_JOYSTICK 0x0264
#define GLUT_OWNS_JOYSTICK 0x0265
#define GLUT_JOYSTICK_BUTTONS 0x0266
#define GLUT_JOYSTICK_AXES 0x0267
#define GLUT_JOYSTICK_POLL_RATE 0x0268

/* ---- glutLayerGet queries and glutUseLayer layers ------------------------ */
#define GLUT_OVERLAY_POSSIBLE 0x0320
#define GLUT_LAYER_IN_USE 0x0321
#define GLUT_HAS_OVERLAY 0x0322
#define GLUT_TRANSPARENT_INDEX 0x0323
#define GLUT_NORMAL_DAMAGED 0x0324
#define GLUT_OVERLAY_DAMAGED 0x0325
#define GLUT_NORMAL 0x0000
#define GLUT_OVERLAY 0x0001

/* ---- glutVideoResizeGet queries ------------------------------------------ */
#define GLUT_VIDEO_RESIZE_POSSIBLE 0x0384
#define GLUT_VIDEO_RESIZE_IN_USE 0x0385
#define GLUT_VIDEO_RESIZE_X_DELTA 0x0386
#define GLUT_VIDEO_RESIZE_Y_DELTA 0x0387
#define GLUT_VIDEO_RESIZE_WIDTH_DELTA 0x0388
#define GLUT_VIDEO_RESIZE_HEIGHT_DELTA 0x0389
#define GLUT_VIDEO_RESIZE_X 0x038A
#define GLUT_VIDEO_RESIZE_Y 0x038B
#define GLUT_VIDEO_RESIZE_WIDTH 0x038C
#define GLUT_VIDEO_RESIZE_HEIGHT 0x038D

/* ---- glutGameModeGet queries --------------------------------------------- */
#define GLUT_GAME_MODE_ACTIVE 0x0000
#define GLUT_GAME_MODE_POSSIBLE 0x0001
#define GLUT_GAME_MODE_WIDTH 0x0002
#define GLUT_GAME_MODE_HEIGHT 0x0003
#define GLUT_GAME_MODE_PIXEL_DEPTH 0x0004
#define GLUT_GAME_MODE_REFRESH_RATE 0x0005
#define GLUT_GAME_MODE_DISPLAY_CHANGED 0x0006

/* ---- Cursors (glutSetCursor) --------------------------------------------- */
#define GLUT_CURSOR_RIGHT_ARROW 0x0000
#define GLUT_CURSOR_LEFT_ARROW 0x0001
#define GLUT_CURSOR_INFO 0x0002
#define GLUT_CURSOR_DESTROY 0x0003
#define GLUT_CURSOR_HELP 0x0004
#define GLUT_CURSOR_CYCLE 0x0005
#define GLUT_CURSOR_SPRAY 0x0006
#define GLUT_CURSOR_WAIT 0x0007
#define GLUT_CURSOR_TEXT 0x0008
#define GLUT_CURSOR_CROSSHAIR 0x0009
#define GLUT_CURSOR_UP_DOWN 0x000A
#define GLUT_CURSOR_LEFT_RIGHT 0x000B
#define GLUT_CURSOR_TOP_SIDE 0x000C
#define GLUT_CURSOR_BOTTOM_SIDE 0x000D
#define GLUT_CURSOR_LEFT_SIDE 0x000E
#define GLUT_CURSOR_RIGHT_SIDE 0x000F
#define GLUT_CURSOR_TOP_LEFT_CORNER 0x0010
#define GLUT_CURSOR_TOP_RIGHT_CORNER 0x0011
#define GLUT_CURSOR_BOTTOM_RIGHT_CORNER 0x0012
#define GLUT_CURSOR_BOTTOM_LEFT_CORNER 0x0013
#define GLUT_CURSOR_INHERIT 0x0064
#define GLUT_CURSOR_NONE 0x0065
#define GLUT_CURSOR_FULL_CROSSHAIR 0x0066

/* ---- Colormap components (glutGetColor) ---------------------------------- */
#define GLUT_RED 0x0000
#define GLUT_GREEN 0x0001
#define GLUT_BLUE 0x0002

/* ---- Key repeat (glutSetKeyRepeat) and joystick buttons ------------------ */
#define GLUT_KEY_REPEAT_OFF 0x0000
#define GLUT_KEY_REPEAT_ON 0x0001
#define GLUT_KEY_REPEAT_DEFAULT 0x0002
#define GLUT_JOYSTICK_BUTTON_A 0x0001
#define GLUT_JOYSTICK_BUTTON_B 0x0002
#define GLUT_JOYSTICK_BUTTON_C 0x0004
#define GLUT_JOYSTICK_BUTTON_D 0x0008

/* ========================================================================== */
/* Entry points                                                               */
/* ========================================================================== */

/* ---- Initialization and the event loop ----------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutInit(int* argcp, char** argv);
TESSEL_GLAPI void TESSEL_APIENTRY glutInitDisplayMode(unsigned int mode);
TESSEL_GLAPI void TESSEL_APIENTRY glutInitDisplayString(const char* string);
TESSEL_GLAPI void TESSEL_APIENTRY glutInitWindowPosition(int x, int y);
TESSEL_GLAPI void TESSEL_APIENTRY glutInitWindowSize(int width, int height);
TESSEL_GLAPI void TESSEL_APIENTRY glutMainLoop(void);
/* freeglut: one iteration of the loop, leave the loop, shut down */
TESSEL_GLAPI void TESSEL_APIENTRY glutMainLoopEvent(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutLeaveMainLoop(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutExit(void);

/* ---- Windows ------------------------------------------------------------- */
TESSEL_GLAPI int TESSEL_APIENTRY glutCreateWindow(const char* title);
TESSEL_GLAPI int TESSEL_APIENTRY glutCreateSubWindow(int win, int x, int y, int width, int height);
TESSEL_GLAPI void TESSEL_APIENTRY glutDestroyWindow(int win);
TESSEL_GLAPI int TESSEL_APIENTRY glutGetWindow(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetWindow(int win);
TESSEL_GLAPI void TESSEL_APIENTRY glutPostRedisplay(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutPostWindowRedisplay(int win);
TESSEL_GLAPI void TESSEL_APIENTRY glutSwapBuffers(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetWindowTitle(const char* title);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetIconTitle(const char* title);
TESSEL_GLAPI void TESSEL_APIENTRY glutPositionWindow(int x, int y);
TESSEL_GLAPI void TESSEL_APIENTRY glutReshapeWindow(int width, int height);
TESSEL_GLAPI void TESSEL_APIENTRY glutPopWindow(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutPushWindow(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutIconifyWindow(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutShowWindow(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutHideWindow(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutFullScreen(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutFullScreenToggle(void); /* freeglut */
TESSEL_GLAPI void TESSEL_APIENTRY glutLeaveFullScreen(void);  /* freeglut */
TESSEL_GLAPI void TESSEL_APIENTRY glutSetCursor(int cursor);
TESSEL_GLAPI void TESSEL_APIENTRY glutWarpPointer(int x, int y);

/* ---- Overlays ------------------------------------------------------------ */
TESSEL_GLAPI void TESSEL_APIENTRY glutEstablishOverlay(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutRemoveOverlay(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutUseLayer(GLenum layer);
TESSEL_GLAPI void TESSEL_APIENTRY glutPostOverlayRedisplay(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutPostWindowOverlayRedisplay(int win);
TESSEL_GLAPI void TESSEL_APIENTRY glutShowOverlay(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutHideOverlay(void);

/* ---- Menus --------------------------------------------------------------- */
TESSEL_GLAPI int TESSEL_APIENTRY glutCreateMenu(void (*func)(int value));
TESSEL_GLAPI void TESSEL_APIENTRY glutDestroyMenu(int menu);
TESSEL_GLAPI int TESSEL_APIENTRY glutGetMenu(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetMenu(int menu);
TESSEL_GLAPI void TESSEL_APIENTRY glutAddMenuEntry(const char* label, int value);
TESSEL_GLAPI void TESSEL_APIENTRY glutAddSubMenu(const char* label, int submenu);
TESSEL_GLAPI void TESSEL_APIENTRY glutChangeToMenuEntry(int item, const char* label, int value);
TESSEL_GLAPI void TESSEL_APIENTRY glutChangeToSubMenu(int item, const char* label, int submenu);
TESSEL_GLAPI void TESSEL_APIENTRY glutRemoveMenuItem(int item);
TESSEL_GLAPI void TESSEL_APIENTRY glutAttachMenu(int button);
TESSEL_GLAPI void TESSEL_APIENTRY glutDetachMenu(int button);

/* ---- Callbacks: window and input ----------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutDisplayFunc(void (*func)(void));
TESSEL_GLAPI void TESSEL_APIENTRY glutOverlayDisplayFunc(void (*func)(void));
TESSEL_GLAPI void TESSEL_APIENTRY glutReshapeFunc(void (*func)(int width, int height));
TESSEL_GLAPI void TESSEL_APIENTRY glutKeyboardFunc(void (*func)(unsigned char key, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutKeyboardUpFunc(void (*func)(unsigned char key, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutSpecialFunc(void (*func)(int key, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutSpecialUpFunc(void (*func)(int key, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutMouseFunc(void (*func)(int button, int state, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutMotionFunc(void (*func)(int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutPassiveMotionFunc(void (*func)(int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutEntryFunc(void (*func)(int state));
TESSEL_GLAPI void TESSEL_APIENTRY glutVisibilityFunc(void (*func)(int state));
TESSEL_GLAPI void TESSEL_APIENTRY glutWindowStatusFunc(void (*func)(int state));
/* freeglut: wheel (wheel number, direction +1/-1), window moved, window closed */
TESSEL_GLAPI void TESSEL_APIENTRY glutMouseWheelFunc(void (*func)(int wheel, int direction, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutPositionFunc(void (*func)(int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutCloseFunc(void (*func)(void));
TESSEL_GLAPI void TESSEL_APIENTRY glutWMCloseFunc(void (*func)(void));

/* ---- Callbacks: global --------------------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutIdleFunc(void (*func)(void));
TESSEL_GLAPI void TESSEL_APIENTRY glutTimerFunc(unsigned int millis, void (*func)(int value), int value);
TESSEL_GLAPI void TESSEL_APIENTRY glutMenuStateFunc(void (*func)(int state));
TESSEL_GLAPI void TESSEL_APIENTRY glutMenuStatusFunc(void (*func)(int status, int x, int y));

/* ---- Callbacks: other input devices -------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutSpaceballMotionFunc(void (*func)(int x, int y, int z));
TESSEL_GLAPI void TESSEL_APIENTRY glutSpaceballRotateFunc(void (*func)(int x, int y, int z));
TESSEL_GLAPI void TESSEL_APIENTRY glutSpaceballButtonFunc(void (*func)(int button, int state));
TESSEL_GLAPI void TESSEL_APIENTRY glutButtonBoxFunc(void (*func)(int button, int state));
TESSEL_GLAPI void TESSEL_APIENTRY glutDialsFunc(void (*func)(int dial, int value));
TESSEL_GLAPI void TESSEL_APIENTRY glutTabletMotionFunc(void (*func)(int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutTabletButtonFunc(void (*func)(int button, int state, int x, int y));
TESSEL_GLAPI void TESSEL_APIENTRY glutJoystickFunc(void (*func)(unsigned int buttonMask, int x, int y, int z),
                                                   int pollInterval);
TESSEL_GLAPI void TESSEL_APIENTRY glutForceJoystickFunc(void);

/* ---- State --------------------------------------------------------------- */
TESSEL_GLAPI int TESSEL_APIENTRY glutGet(GLenum type);
TESSEL_GLAPI int TESSEL_APIENTRY glutDeviceGet(GLenum type);
TESSEL_GLAPI int TESSEL_APIENTRY glutLayerGet(GLenum type);
TESSEL_GLAPI int TESSEL_APIENTRY glutGetModifiers(void);
TESSEL_GLAPI int TESSEL_APIENTRY glutExtensionSupported(const char* name);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetOption(GLenum option, int value); /* freeglut */
TESSEL_GLAPI void TESSEL_APIENTRY glutIgnoreKeyRepeat(int ignore);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetKeyRepeat(int repeatMode);
TESSEL_GLAPI void TESSEL_APIENTRY glutReportErrors(void);

/* ---- Color index colormaps ----------------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutSetColor(int cell, GLfloat red, GLfloat green, GLfloat blue);
TESSEL_GLAPI GLfloat TESSEL_APIENTRY glutGetColor(int cell, int component);
TESSEL_GLAPI void TESSEL_APIENTRY glutCopyColormap(int win);

/* ---- Fonts --------------------------------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutBitmapCharacter(void* font, int character);
TESSEL_GLAPI int TESSEL_APIENTRY glutBitmapWidth(void* font, int character);
TESSEL_GLAPI int TESSEL_APIENTRY glutBitmapLength(void* font, const unsigned char* string);
TESSEL_GLAPI void TESSEL_APIENTRY glutStrokeCharacter(void* font, int character);
TESSEL_GLAPI int TESSEL_APIENTRY glutStrokeWidth(void* font, int character);
TESSEL_GLAPI int TESSEL_APIENTRY glutStrokeLength(void* font, const unsigned char* string);
/* freeglut: font heights and whole strings */
TESSEL_GLAPI int TESSEL_APIENTRY glutBitmapHeight(void* font);
TESSEL_GLAPI GLfloat TESSEL_APIENTRY glutStrokeHeight(void* font);
TESSEL_GLAPI void TESSEL_APIENTRY glutBitmapString(void* font, const unsigned char* string);
TESSEL_GLAPI void TESSEL_APIENTRY glutStrokeString(void* font, const unsigned char* string);

/* ---- Geometric objects --------------------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutWireSphere(GLdouble radius, GLint slices, GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireCube(GLdouble size);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidCube(GLdouble size);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides,
                                                GLint rings);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides,
                                                 GLint rings);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireDodecahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidDodecahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireTeapot(GLdouble size);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidTeapot(GLdouble size);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireOctahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidOctahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireTetrahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidTetrahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutWireIcosahedron(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidIcosahedron(void);
/* freeglut */
TESSEL_GLAPI void TESSEL_APIENTRY glutWireCylinder(GLdouble radius, GLdouble height, GLint slices,
                                                   GLint stacks);
TESSEL_GLAPI void TESSEL_APIENTRY glutSolidCylinder(GLdouble radius, GLdouble height, GLint slices,
                                                    GLint stacks);

/* ---- Context version and profile (freeglut 2.6+) -------------------------- */
#define GLUT_INIT_MAJOR_VERSION 0x0200
#define GLUT_INIT_MINOR_VERSION 0x0201
#define GLUT_INIT_FLAGS 0x0202
#define GLUT_INIT_PROFILE 0x0203
#define GLUT_DEBUG 0x0001
#define GLUT_FORWARD_COMPATIBLE 0x0002
#define GLUT_CORE_PROFILE 0x0001
#define GLUT_COMPATIBILITY_PROFILE 0x0002
TESSEL_GLAPI void TESSEL_APIENTRY glutInitContextVersion(int major, int minor);
TESSEL_GLAPI void TESSEL_APIENTRY glutInitContextFlags(int flags);
TESSEL_GLAPI void TESSEL_APIENTRY glutInitContextProfile(int profile);
/* The address of a GL entry point by name, for loaders (glad, ...); null for a name Tessel's
 * GL does not define. */
typedef void (*GLUTproc)(void);
TESSEL_GLAPI GLUTproc TESSEL_APIENTRY glutGetProcAddress(const char* procName);

/* ---- Video resizing ------------------------------------------------------ */
TESSEL_GLAPI int TESSEL_APIENTRY glutVideoResizeGet(GLenum param);
TESSEL_GLAPI void TESSEL_APIENTRY glutSetupVideoResizing(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutStopVideoResizing(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutVideoResize(int x, int y, int width, int height);
TESSEL_GLAPI void TESSEL_APIENTRY glutVideoPan(int x, int y, int width, int height);

/* ---- Game mode ----------------------------------------------------------- */
TESSEL_GLAPI void TESSEL_APIENTRY glutGameModeString(const char* string);
TESSEL_GLAPI int TESSEL_APIENTRY glutEnterGameMode(void);
TESSEL_GLAPI void TESSEL_APIENTRY glutLeaveGameMode(void);
TESSEL_GLAPI int TESSEL_APIENTRY glutGameModeGet(GLenum mode);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* TESSEL_COMPAT_GL_GLUT_H */
