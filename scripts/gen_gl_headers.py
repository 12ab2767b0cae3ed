#!/usr/bin/env python3
"""Writes Tessel's GL/glext.h, GL/glcorearb.h and GL/glew.h (with src/gl/glew_flags.inc) from the Khronos API registry (gl.xml).

The registry is the specification's own machine-readable list of every enumerant and entry
point by version (Debian: apt-get install khronos-api, /usr/share/khronos-api/gl.xml). The
headers declare what GL 1.2 to 3.3 add (glext.h, for use after GL/gl.h) and the whole 3.3
core profile (glcorearb.h, standalone). As in every glext.h, prototypes are declared when
GL_GLEXT_PROTOTYPES is defined; the PFNGL...PROC pointer types always are.

    scripts/gen_gl_headers.py [path/to/gl.xml]

Run it again only to change what the headers cover; the output is committed.
"""
import os
import sys
import xml.etree.ElementTree as ET

LAST = (3, 3)  # the newest version Tessel implements

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, '..', 'include', 'compat', 'GL')

# The scalar types beyond GL 1.1's (gl.h has those), with the C types the registry's
# khrplatform names stand for on the platforms Tessel builds for (LP64 and ILP32 Linux).
EXTRA_TYPES = """\
#ifndef TESSEL_GL_EXTRA_TYPES
#define TESSEL_GL_EXTRA_TYPES 1
#include <stdint.h>
typedef unsigned short GLhalf;
typedef int64_t GLint64;
typedef uint64_t GLuint64;
typedef struct __GLsync* GLsync;
typedef void (*GLDEBUGPROC)(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                            const GLchar* message, const void* userParam);
typedef char GLcharARB;
typedef unsigned int GLhandleARB;
typedef ptrdiff_t GLintptrARB;
typedef ptrdiff_t GLsizeiptrARB;
typedef int64_t GLint64EXT;
typedef uint64_t GLuint64EXT;
#endif
"""

BASE_TYPES = """\
#ifndef TESSEL_GL_SCALAR_TYPES
#define TESSEL_GL_SCALAR_TYPES 1
#include <stddef.h>
typedef unsigned int GLenum;
typedef unsigned char GLboolean;
typedef unsigned int GLbitfield;
typedef void GLvoid;
typedef signed char GLbyte;
typedef short GLshort;
typedef int GLint;
typedef int GLsizei;
typedef unsigned char GLubyte;
typedef unsigned short GLushort;
typedef unsigned int GLuint;
typedef float GLfloat;
typedef float GLclampf;
typedef double GLdouble;
typedef double GLclampd;
typedef char GLchar;
typedef ptrdiff_t GLintptr;
typedef ptrdiff_t GLsizeiptr;
#endif
"""


def text_of(elem):
    """A <proto> or <param> as C text."""
    return ' '.join(''.join(elem.itertext()).split())


def load(path):
    root = ET.parse(path).getroot()
    global ALIASES, ARG_NAMES, EXTENSIONS
    ALIASES, ARG_NAMES, EXTENSIONS = {}, {}, []
    for c in root.find('commands').findall('command'):
        name = c.find('proto').find('name').text
        alias = c.find('alias')
        if alias is not None:
            ALIASES[name] = alias.get('name')
        ARG_NAMES[name] = [p.find('name').text for p in c.findall('param')]
    for e in root.find('extensions').findall('extension'):
        if 'gl' in (e.get('supported') or '').split('|'):
            EXTENSIONS.append(e)
    enums = {}
    for group in root.findall('enums'):
        for e in group.findall('enum'):
            if e.get('api') not in (None, 'gl'):
                continue
            enums.setdefault(e.get('name'), e.get('value'))
    commands = {}
    for c in root.find('commands').findall('command'):
        proto = c.find('proto')
        name = proto.find('name').text
        ret = text_of(proto)[: -len(name)].strip()
        params = [text_of(p) for p in c.findall('param')]
        commands[name] = (ret, params)
    features = []
    for f in root.findall('feature'):
        if f.get('api') != 'gl':
            continue
        version = tuple(int(x) for x in f.get('number').split('.'))
        if version > LAST:
            continue
        features.append((version, f))
    return enums, commands, features


def items(feature, profile):
    """The enums and commands a version adds, minus what `profile` removes, in order."""
    en, cm = [], []
    for req in feature.findall('require'):
        if req.get('profile') not in (None, profile):
            continue
        for e in req.findall('enum'):
            en.append(e.get('name'))
        for c in req.findall('command'):
            cm.append(c.get('name'))
    return en, cm


def removed(features, profile):
    gone = set()
    for _, f in features:
        for rem in f.findall('remove'):
            if rem.get('profile') == profile:
                gone.update(x.get('name') for x in rem if x.get('name'))
    return gone


# Extensions with entry points of their own that GL itself does not alias to a core one, which
# Tessel defines by hand over the core ones (src/gl/ext_aliases.cpp).
HAND_WRITTEN = {
    'GL_EXT_framebuffer_object': {'glBindFramebufferEXT', 'glBindRenderbufferEXT'},
    'GL_ARB_shader_objects': {'glDeleteObjectARB', 'glGetHandleARB', 'glGetObjectParameterfvARB',
                              'glGetObjectParameterivARB', 'glGetInfoLogARB', 'glGetAttachedObjectsARB'},
}


# Extensions made core after 3.3 whose enumerants are older ones put to new uses (a per-texture
# GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_STENCIL_INDEX8 textures, ...), and GL_EXT_gpu_shader4, whose
# GLSL side (#extension GL_EXT_gpu_shader4) the shader compiler does not take.
EXCLUDED = {'GL_ARB_seamless_cubemap_per_texture', 'GL_ARB_texture_stencil8', 'GL_ARB_vertex_type_10f_11f_11f_rev',
            'GL_ARB_texture_buffer_object_rgb32', 'GL_EXT_gpu_shader4'}


def alias_extensions(core_names, core_enums, enums):
    """The ARB and EXT extensions whose every entry point is a GL 1.0-3.3 one or, by the
    registry's <alias>, another name of one (GL_ARB_vertex_buffer_object's glGenBuffersARB is
    glGenBuffers), plus HAND_WRITTEN: what old code calls by its extension names. Extensions
    without entry points count when each of their enumerants is a GL 1.0-3.3 one under its
    name with the suffix (GL_ARB_fragment_shader's GL_FRAGMENT_SHADER_ARB)."""
    out = []
    for e in EXTENSIONS:
        name = e.get('name')
        if not name.startswith(('GL_ARB_', 'GL_EXT_')) or name in EXCLUDED:
            continue
        cmds = [c for req in e.findall('require') for c in (x.get('name') for x in req.findall('command'))]
        if not cmds:
            ens = [x.get('name') for req in e.findall('require') for x in req.findall('enum')]
            def core_value(n):
                base = n[:-4] if n.endswith(('_ARB', '_EXT')) else n
                return base in core_enums and enums.get(base) == enums.get(n)
            if ens and all(core_value(n) for n in ens):
                out.append(e)
            continue
        hand = HAND_WRITTEN.get(name, set())
        if all(c in core_names or ALIASES.get(c) in core_names or c in hand for c in cmds):
            out.append(e)
    return out


def write_aliases(aliased, core_names, commands):
    """src/gl/ext_aliases.inc: each extension name of a core entry point, as a call of it."""
    rows, done = [], set()
    for e in aliased:
        for c in items(e, 'compatibility')[1]:
            if c in core_names or c in done or c not in ALIASES:
                continue
            done.add(c)
            ret, params = commands[c]
            args = ', '.join(ARG_NAMES[c])
            rows.append(f'TESSEL_ALIAS({ret}, {c}, {ALIASES[c]}, ({", ".join(params) or "void"}), ({args}))')
    with open(os.path.join(HERE, '..', 'src', 'gl', 'ext_aliases.inc'), 'w') as fh:
        fh.write('// Generated by scripts/gen_gl_headers.py: the ARB and EXT names of GL 1.0 to 3.3 entry\n')
        fh.write('// points (the registry\'s <alias>), each calling the core one.\n// clang-format off\n')
        for r in sorted(rows):
            fh.write(r + '\n')
    with open(os.path.join(HERE, '..', 'src', 'gl', 'ext_names.inc'), 'w') as fh:
        fh.write('// Generated by scripts/gen_gl_headers.py: the extensions whose entry points are all there\n')
        fh.write('// under their own names (alias_extensions), for a compatibility context\'s GL_EXTENSIONS.\n')
        fh.write('// clang-format off\n')
        for e in sorted(x.get('name') for x in aliased):
            fh.write(f'"{e}",\n')


def block(name, en, cm, enums, commands, seen):
    """One version's guarded block; what an earlier block declared (3.1 and 3.2 repeat some
    of 3.0) is left out. The guards are the GL_VERSION_x_y names in both headers, so a
    version the first included header declared is skipped by the second."""
    en = [e for e in en if e not in seen]
    cm = [c for c in cm if c not in seen]
    seen.update(en)
    seen.update(cm)
    out = [f'#ifndef {name}', f'#define {name} 1']
    for e in en:
        out.append(f'#define {e} {enums[e]}')
    for c in cm:
        ret, params = commands[c]
        out.append(f'typedef {ret} (APIENTRYP PFN{c.upper()}PROC)({", ".join(params) or "void"});')
    out.append('#ifdef GL_GLEXT_PROTOTYPES')
    for c in cm:
        ret, params = commands[c]
        out.append(f'GLAPI {ret} APIENTRY {c}({", ".join(params) or "void"});')
    out.append('#endif')
    out.append(f'#endif /* {name} */')
    return '\n'.join(out) + '\n'


HEAD = """/* clang-format off */
/*
 * Tessel compatibility header: <GL/{file}>
 *
 * Generated by scripts/gen_gl_headers.py from the Khronos API registry (gl.xml):
 * {what}.
 * The names, numbers and parameter lists are those the OpenGL specification fixes. Entry
 * points are declared when GL_GLEXT_PROTOTYPES is defined (or by GL/glew.h); the function
 * pointer types (PFNGL...PROC) always are, for loaders.
 */
"""

LINKAGE = """#ifndef APIENTRY
#define APIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY*
#endif
#ifndef GLAPI
#if defined(__GNUC__) || defined(__clang__)
#define GLAPI extern __attribute__((visibility("default")))
#else
#define GLAPI extern
#endif
#endif
"""


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else '/usr/share/khronos-api/gl.xml'
    enums, commands, features = load(path)

    # glext.h: what 1.2 .. 3.3 add, compatibility profile (after GL/gl.h, which has 1.1).
    parts = [HEAD.format(file='glext.h', what='every enumerant and entry point OpenGL 1.2 to 3.3\n * '
                         'add to 1.1, compatibility profile'),
             '#ifndef __gl_glext_h_\n#define __gl_glext_h_ 1\n#include <GL/gl.h>\n',
             '#ifdef __cplusplus\nextern "C" {\n#endif\n', LINKAGE, EXTRA_TYPES]
    seen = set()
    for version, f in features:
        if version <= (1, 1):
            continue
        en, cm = items(f, 'compatibility')
        parts.append(block(f.get('name'), en, cm, enums, commands, seen))
    core_names, core_enums = set(), set()
    for version, f in features:
        en, cm = items(f, 'compatibility')
        core_names.update(cm)
        core_enums.update(en)
    aliased = alias_extensions(core_names, core_enums, enums)
    for e in aliased:
        en, cm = items(e, 'compatibility')
        parts.append(block(e.get('name'), en, cm, enums, commands, seen))
    parts.append('#ifdef __cplusplus\n}\n#endif\n#endif /* __gl_glext_h_ */\n')
    with open(os.path.join(OUT, 'glext.h'), 'w') as fh:
        fh.write('\n'.join(parts))

    # glcorearb.h: the 3.3 core profile, standalone.
    gone = removed(features, 'core')
    parts = [HEAD.format(file='glcorearb.h', what='the OpenGL 3.3 core profile, 1.0 to 3.3 without\n * '
                         'what the core profile removes'),
             '#ifndef __gl_glcorearb_h_\n#define __gl_glcorearb_h_ 1\n',
             '#ifdef __cplusplus\nextern "C" {\n#endif\n', LINKAGE, BASE_TYPES, EXTRA_TYPES]
    seen = set()
    for version, f in features:
        en, cm = items(f, 'core')
        en = [e for e in en if e not in gone]
        cm = [c for c in cm if c not in gone]
        name = f.get('name')
        if version <= (1, 1):
            # GL/gl.h defines GL_VERSION_1_1 for the whole of 1.1: the core subset takes its
            # own guard so that both headers can be included.
            name = 'TESSEL_GLCOREARB_' + name[3:]
        parts.append(block(name, en, cm, enums, commands, seen))
    parts.append('#ifdef __cplusplus\n}\n#endif\n#endif /* __gl_glcorearb_h_ */\n')
    with open(os.path.join(OUT, 'glcorearb.h'), 'w') as fh:
        fh.write('\n'.join(parts))

    write_glew(path)

    # Every entry point of GL 1.0 to 3.3 (compatibility) by name, for the GetProcAddress table
    # (src/gl/proc_address.cpp).
    names = []
    seen = set()
    for version, f in features:
        en, cm = items(f, 'compatibility')
        for c in cm:
            if c not in seen:
                seen.add(c)
                names.append(c)
    write_aliases(aliased, core_names, commands)
    for e in aliased:
        for c in items(e, 'compatibility')[1]:
            if c not in seen:
                seen.add(c)
                names.append(c)
    with open(os.path.join(HERE, '..', 'src', 'gl', 'proc_names.inc'), 'w') as fh:
        fh.write('// Generated by scripts/gen_gl_headers.py: the entry points of GL 1.0 to 3.3 and their ARB\n')
        fh.write('// and EXT names (alias_extensions), sorted.\n')
        fh.write('// clang-format off\n')
        for c in sorted(names):
            fh.write(f'TESSEL_PROC({c})\n')


GLEW_HEAD = """/* clang-format off */
/*
 * Tessel compatibility header: <GL/glew.h>
 *
 * GLEW's API over Tessel's OpenGL: every entry point is a function of Tessel's libraries, so
 * glewInit has nothing to load. It succeeds when a context is current, and sets the version
 * flags (GLEW_VERSION_x_y) and extension flags (GLEW_ARB_..., one for every extension of the
 * Khronos registry) to what that context really has. Generated by scripts/gen_gl_headers.py.
 */
#ifndef __glew_h__
#if defined(TESSEL_COMPAT_GL_GL_H) && !defined(GL_GLEXT_PROTOTYPES)
/* As with GLEW itself: gl.h (or glut.h) included first has declared GL without the entry
 * points GLEW provides. */
#error gl.h included before glew.h
#endif
#define __glew_h__ 1
#define __GLEW_H__ 1
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLEW_OK 0
#define GLEW_NO_ERROR 0
#define GLEW_ERROR_NO_GL_VERSION 1
#define GLEW_ERROR_GL_VERSION_10_ONLY 2
#define GLEW_ERROR_GLX_VERSION_11_ONLY 3
#define GLEW_ERROR_NO_GLX_DISPLAY 4
#define GLEW_VERSION 1
#define GLEW_VERSION_MAJOR 2
#define GLEW_VERSION_MINOR 3
#define GLEW_VERSION_MICRO 4
#define GLEW_GET_VAR(x) (x)
#define GLEW_GET_FUN(x) (x)

GLAPI GLboolean glewExperimental;
GLAPI GLenum glewInit(void);
GLAPI GLboolean glewIsSupported(const char* name);
#define glewIsExtensionSupported(x) glewIsSupported(x)
GLAPI GLboolean glewGetExtension(const char* name);
GLAPI const GLubyte* glewGetErrorString(GLenum error);
GLAPI const GLubyte* glewGetString(GLenum name);
"""


def write_glew(root_path):
    root = ET.parse(root_path).getroot()
    exts = sorted({e.get('name') for e in root.find('extensions').findall('extension')
                   if 'gl' in (e.get('supported') or '').split('|') and e.get('name').startswith('GL_')})
    versions = [f'{a}_{b}' for a, b in [(1, 1), (1, 2), (1, 3), (1, 4), (1, 5), (2, 0), (2, 1), (3, 0), (3, 1),
                                         (3, 2), (3, 3), (4, 0), (4, 1), (4, 2), (4, 3), (4, 4), (4, 5), (4, 6)]]
    out = [GLEW_HEAD]
    for v in versions:
        out.append(f'GLAPI GLboolean __GLEW_VERSION_{v};\n#define GLEW_VERSION_{v} __GLEW_VERSION_{v}')
    out.append('#define GLEW_VERSION_1_2_1 GLEW_VERSION_1_2')
    for e in exts:
        n = e[3:]
        out.append(f'GLAPI GLboolean __GLEW_{n};\n#define GLEW_{n} __GLEW_{n}')
    out.append('\n#ifdef __cplusplus\n}\n#endif\n#endif /* __glew_h__ */\n')
    with open(os.path.join(OUT, 'glew.h'), 'w') as fh:
        fh.write('\n'.join(out))
    # The flags' definitions, by name, for glewInit (src/gl/glew.cpp).
    src = os.path.join(HERE, '..', 'src', 'gl', 'glew_flags.inc')
    with open(src, 'w') as fh:
        fh.write('// Generated by scripts/gen_gl_headers.py: GLEW\'s flags, defined, and listed by name.\n')
        fh.write('// clang-format off\n')
        for v in versions:
            fh.write(f'GLboolean __GLEW_VERSION_{v} = GL_FALSE;\n')
        for e in exts:
            fh.write(f'GLboolean __GLEW_{e[3:]} = GL_FALSE;\n')
        fh.write('const VersionFlag kVersionFlags[] = {\n')
        for v in versions:
            a, b = v.split('_')
            fh.write(f'    {{{a}, {b}, &__GLEW_VERSION_{v}}},\n')
        fh.write('};\nconst ExtensionFlag kExtensionFlags[] = {\n')
        for e in exts:
            fh.write(f'    {{"{e}", &__GLEW_{e[3:]}}},\n')
        fh.write('};\n')


if __name__ == '__main__':
    main()
