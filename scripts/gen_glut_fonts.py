#!/usr/bin/env python3
"""Generate src/glut/font_data.cpp: the glyphs of GLUT's nine standard fonts.

Usage (from the repository root):

    apt-get install -y xfonts-base xfonts-75dpi hershey-fonts-data   # generating only
    python3 scripts/gen_glut_fonts.py            # writes src/glut/font_data.cpp
    python3 scripts/gen_glut_fonts.py -o FILE    # writes elsewhere
    python3 scripts/gen_glut_fonts.py --measure-stroke-metrics
        # first re-measures scripts/glut_stroke_metrics.txt (needs gcc,
        # freeglut3-dev, an OpenGL library and xvfb-run), then generates

Standard library only.  The font files are read from the installed Debian
packages, the stroke fonts' metrics from scripts/glut_stroke_metrics.txt;
nothing else is needed and nothing is fetched.

Bitmap fonts
    GLUT's seven bitmap fonts were captured from X11 server fonts.  This script
    reads the very same fonts from their PCF files (gzip-compressed, parsed
    here; the format is the one documented with the X server's libXfont), takes
    characters 32..255 and records for each glyph exactly what GLUT hands to
    glBitmap: width and height of the glyph's bitmap (the X character cell
    rbearing - lbearing by ascent + descent), xorig = -lbearing, yorig =
    descent, the advance, and the rows bottom-up, each padded to whole bytes,
    most significant bit first.  The font height is freeglut's
    glutBitmapHeight(): max_bounds.ascent + max_bounds.descent + 1.

    The Adobe fonts as X11R6 / XFree86 (and so GLUT) had them encoded 0x27 as
    quoteright, 0x2D as minus and 0x60 as quoteleft; today's -iso8859-1 files
    in xfonts-75dpi hold the ASCII apostrophe, hyphen and grave there.  To keep
    GLUT's look those three are taken from the -iso10646-1 file of the same
    font (U+2019, U+2212, U+2018).  Codes that the font does not have
    (127..159) are left empty: as in GLUT 3.7, nothing is drawn for them and
    their width is 0 (freeglut has filler glyphs there).  The X fonts have been
    revised a little since freeglut captured them (the accents of 8x13's small
    letters, a handful of ASCII glyphs of 8x13 and 9x15); those glyphs follow
    today's files.

Stroke fonts
    GLUT's Roman and Mono Roman stroke fonts are the Hershey simplex Roman
    glyphs.  The glyph outlines come from hershey-fonts-data (rowmans.jhf, with
    the few glyphs GLUT draws differently taken from the other Hershey files of
    the package, see STROKE_SOURCES), scaled by 100/21 so that capitals are 100
    units tall, the baseline at y = 0, the top of the font at 119.05 and its
    bottom at -33.33 (glutStrokeHeight 152.381).

    Where each outline sits horizontally and how far the pen then advances are
    GLUT's own choices, not Hershey's.  Those two numbers per glyph were
    measured from freeglut (--measure-stroke-metrics) and are kept in
    scripts/glut_stroke_metrics.txt: the advance (glutStrokeWidthf) and the
    smallest x of the glyph's vertices as glutStrokeCharacter draws them
    (caught with GL_FEEDBACK).  Nothing else is taken from freeglut; the
    outlines are Hershey's.  Each outline is moved so that its smallest x is
    the measured one.  The measurement checks that freeglut's glyph has the
    same number of line segments, the same ink width and the same lowest and
    highest y as the Hershey outline used here; that holds for every glyph
    but the three of SHAPE_DIFFERS ('@', '_' and 127), which GLUT draws with
    outlines Hershey's files do not have.  Those get GLUT's advance, with the
    Hershey outline's ink centred in it.
"""

import argparse
import gzip
import os
import struct
import subprocess
import sys
import textwrap

XFONTS_MISC = "/usr/share/fonts/X11/misc"
XFONTS_75DPI = "/usr/share/fonts/X11/75dpi"
HERSHEY_DIR = "/usr/share/hershey-fonts"
DOC_XFONTS_BASE = "/usr/share/doc/xfonts-base/copyright"
DOC_XFONTS_75DPI = "/usr/share/doc/xfonts-75dpi/copyright"
DOC_HERSHEY = "/usr/share/doc/hershey-fonts-data/copyright"

FIRST_CHAR = 32
LAST_BITMAP_CHAR = 255
LAST_STROKE_CHAR = 127

# GLUT handle value, C++ identifier, directory, PCF file (the XLFD GLUT opens),
# Unicode PCF file of the same face (for the legacy Adobe code points) or None.
BITMAP_FONTS = [
    (2, "Bitmap9By15", XFONTS_MISC, "9x15-ISO8859-1.pcf.gz", None),
    (3, "Bitmap8By13", XFONTS_MISC, "8x13-ISO8859-1.pcf.gz", None),
    (4, "BitmapTimesRoman10", XFONTS_75DPI, "timR10-ISO8859-1.pcf.gz", "timR10.pcf.gz"),
    (5, "BitmapTimesRoman24", XFONTS_75DPI, "timR24-ISO8859-1.pcf.gz", "timR24.pcf.gz"),
    (6, "BitmapHelvetica10", XFONTS_75DPI, "helvR10-ISO8859-1.pcf.gz", "helvR10.pcf.gz"),
    (7, "BitmapHelvetica12", XFONTS_75DPI, "helvR12-ISO8859-1.pcf.gz", "helvR12.pcf.gz"),
    (8, "BitmapHelvetica18", XFONTS_75DPI, "helvR18-ISO8859-1.pcf.gz", "helvR18.pcf.gz"),
]
# The XLFD each GLUT font was made from.
GLUT_XLFD = {
    2: "-misc-fixed-medium-r-normal--15-140-75-75-C-90-iso8859-1",
    3: "-misc-fixed-medium-r-normal--13-120-75-75-C-80-iso8859-1",
    4: "-adobe-times-medium-r-normal--10-100-75-75-p-54-iso8859-1",
    5: "-adobe-times-medium-r-normal--24-240-75-75-p-124-iso8859-1",
    6: "-adobe-helvetica-medium-r-normal--10-100-75-75-p-56-iso8859-1",
    7: "-adobe-helvetica-medium-r-normal--12-120-75-75-p-67-iso8859-1",
    8: "-adobe-helvetica-medium-r-normal--18-180-75-75-p-98-iso8859-1",
}
# Adobe's original ISO 8859-1 encoding (X11R6, XFree86): code -> Unicode glyph.
ADOBE_LEGACY_CODES = {0x27: 0x2019, 0x2D: 0x2212, 0x60: 0x2018}

# Stroke fonts ---------------------------------------------------------------
HERSHEY_SCALE = 100.0 / 21.0   # Hershey units -> GLUT units (cap height 21 -> 100)
HERSHEY_BASELINE = 9           # Hershey y of the baseline (y grows downwards)
HERSHEY_TOP, HERSHEY_BOTTOM = -16, 16

# The stroke fonts: C++ identifier, name (in font_data.cpp and in the metrics
# file), the freeglut font measured for it (MEASURE_C's fonts[], same order).
STROKE_FONTS = [
    ("StrokeRoman", "Roman", "GLUT_STROKE_ROMAN"),
    ("StrokeMonoRoman", "MonoRoman", "GLUT_STROKE_MONO_ROMAN"),
]
STROKE_METRICS_FILE = "glut_stroke_metrics.txt"   # next to this script

# Character -> (Hershey file, its character, transformation).  Default is the
# same character of rowmans.jhf (simplex Roman).  GLUT draws these few
# differently; the equivalent Hershey glyphs are used instead:
#   '  a straight tick: the left stroke of rowmans '"'
#   *  the asterisk centred on the math axis (futural.jhf)
#   /  the steeper slash of symbolic.jhf
#   ^  the open wedge of futural.jhf
#   _  the underscore at the bottom of the font (futural.jhf)
#   `  the wedge-shaped grave of futuram.jhf
# ('@' and the character 127 stay rowmans' glyphs; GLUT's differ.)
STROKE_SOURCES = {
    0x27: ("rowmans.jhf", 0x22, "first-stroke"),
    0x2A: ("futural.jhf", 0x2A, None),
    0x2F: ("symbolic.jhf", 0x27, None),
    0x5E: ("futural.jhf", 0x5E, None),
    0x5F: ("futural.jhf", 0x5F, None),
    0x60: ("futuram.jhf", 0x60, None),
}
# The glyphs whose GLUT outline no Hershey glyph of the package matches:
# GLUT's '@' is a smaller one (62 x 62 units, not 100 x 100), its '_' a thin
# rectangle 104.8 units wide (the Hershey underscore is a line 85.7 long) and
# its 127 a circle crossed by a long stroke.  Their Hershey ink is centred in
# GLUT's advance; the measured smallest x is not used.
SHAPE_DIFFERS = (0x40, 0x5F, 0x7F)


def die(msg):
    sys.exit("gen_glut_fonts.py: " + msg)


# --------------------------------------------------------------------------
# PCF (X11 Portable Compiled Format) reader
# --------------------------------------------------------------------------
PCF_PROPERTIES = 1 << 0
PCF_ACCELERATORS = 1 << 1
PCF_METRICS = 1 << 2
PCF_BITMAPS = 1 << 3
PCF_BDF_ENCODINGS = 1 << 5
PCF_BDF_ACCELERATORS = 1 << 8

PCF_GLYPH_PAD_MASK = 3
PCF_BYTE_MASK = 1 << 2        # set: most significant byte first
PCF_BIT_MASK = 1 << 3         # set: most significant bit first
PCF_SCAN_UNIT_MASK = 3 << 4
PCF_COMPRESSED_METRICS = 0x100


class PcfFont:
    """The parts of a PCF font GLUT needs: properties, per-glyph metrics and
    bitmaps (as rows of 0/1 pixels, top row first), encoding, bounds."""

    def __init__(self, path):
        self.path = path
        try:
            with gzip.open(path, "rb") as f:
                self.data = f.read()
        except OSError as e:
            die("cannot read %s: %s" % (path, e))
        if self.data[:4] != b"\x01fcp":
            die("%s is not a PCF font" % path)
        (count,) = struct.unpack_from("<i", self.data, 4)
        self.tables = {}
        for i in range(count):
            ttype, _fmt, size, offset = struct.unpack_from("<iiii", self.data, 8 + 16 * i)
            self.tables[ttype] = (offset, size)
        self._read_properties()
        self._read_accelerators()
        self._read_metrics()
        self._read_bitmaps()
        self._read_encodings()

    def _table(self, ttype):
        if ttype not in self.tables:
            die("%s has no PCF table %d" % (self.path, ttype))
        offset, _ = self.tables[ttype]
        (fmt,) = struct.unpack_from("<i", self.data, offset)
        order = ">" if fmt & PCF_BYTE_MASK else "<"
        return fmt, offset + 4, order

    def _read_properties(self):
        fmt, p, o = self._table(PCF_PROPERTIES)
        (n,) = struct.unpack_from(o + "i", self.data, p)
        p += 4
        raw = []
        for _ in range(n):
            raw.append(struct.unpack_from(o + "iBi", self.data, p))
            p += 9
        if n & 3:
            p += 4 - (n & 3)
        (string_size,) = struct.unpack_from(o + "i", self.data, p)
        p += 4
        strings = self.data[p:p + string_size]

        def cstr(off):
            return strings[off:strings.index(b"\0", off)].decode("latin-1")

        self.props = {}
        for name, is_string, value in raw:
            self.props[cstr(name)] = cstr(value) if is_string else value

    def _read_accelerators(self):
        ttype = PCF_BDF_ACCELERATORS if PCF_BDF_ACCELERATORS in self.tables else PCF_ACCELERATORS
        fmt, p, o = self._table(ttype)
        p += 8  # noOverlap .. padding: eight one-byte fields
        self.font_ascent, self.font_descent, _ = struct.unpack_from(o + "3i", self.data, p)
        p += 12
        self.min_bounds = struct.unpack_from(o + "5h", self.data, p)
        p += 12
        self.max_bounds = struct.unpack_from(o + "5h", self.data, p)

    def _read_metrics(self):
        fmt, p, o = self._table(PCF_METRICS)
        self.metrics = []  # (lbearing, rbearing, width, ascent, descent)
        if fmt & PCF_COMPRESSED_METRICS:
            (n,) = struct.unpack_from(o + "h", self.data, p)
            p += 2
            for _ in range(n):
                self.metrics.append(tuple(b - 0x80 for b in self.data[p:p + 5]))
                p += 5
        else:
            (n,) = struct.unpack_from(o + "i", self.data, p)
            p += 4
            for _ in range(n):
                self.metrics.append(struct.unpack_from(o + "5h", self.data, p))
                p += 12

    def _read_bitmaps(self):
        fmt, p, o = self._table(PCF_BITMAPS)
        (n,) = struct.unpack_from(o + "i", self.data, p)
        p += 4
        if n != len(self.metrics):
            die("%s: %d bitmaps for %d metrics" % (self.path, n, len(self.metrics)))
        offsets = struct.unpack_from(o + "%di" % n, self.data, p)
        p += 4 * n
        sizes = struct.unpack_from(o + "4i", self.data, p)
        p += 16
        bits = self.data[p:p + sizes[fmt & PCF_GLYPH_PAD_MASK]]
        pad = 1 << (fmt & PCF_GLYPH_PAD_MASK)
        unit = 1 << ((fmt & PCF_SCAN_UNIT_MASK) >> 4)
        msb_byte = bool(fmt & PCF_BYTE_MASK)
        msb_bit = bool(fmt & PCF_BIT_MASK)
        self.bitmaps = []
        for index, (lb, rb, _w, asc, desc) in enumerate(self.metrics):
            width, height = rb - lb, asc + desc
            stride = ((width + 7) // 8 + pad - 1) // pad * pad
            rows = []
            for r in range(max(height, 0)):
                start = offsets[index] + r * stride
                row = bytearray(bits[start:start + stride])
                if msb_byte != msb_bit and unit > 1:
                    for u in range(0, len(row), unit):
                        row[u:u + unit] = row[u:u + unit][::-1]
                if not msb_bit:
                    row = bytearray(int("{:08b}".format(b)[::-1], 2) for b in row)
                rows.append([(row[x >> 3] >> (7 - (x & 7))) & 1 for x in range(max(width, 0))])
            self.bitmaps.append(rows)

    def _read_encodings(self):
        fmt, p, o = self._table(PCF_BDF_ENCODINGS)
        min2, max2, min1, max1, self.default_char = struct.unpack_from(o + "5h", self.data, p)
        p += 10
        cols = max2 - min2 + 1
        n = cols * (max1 - min1 + 1)
        index = struct.unpack_from(o + "%dH" % n, self.data, p)
        self.encoding = {}
        for b1 in range(min1, max1 + 1):
            for b2 in range(min2, max2 + 1):
                g = index[(b1 - min1) * cols + (b2 - min2)]
                if g != 0xFFFF:
                    self.encoding[(b1 << 8) | b2] = g

    def glyph(self, code):
        g = self.encoding.get(code)
        if g is None:
            return None
        return self.metrics[g], self.bitmaps[g]


def glbitmap_bytes(rows, width):
    """Rows top-down as 0/1 lists -> glBitmap bytes: bottom row first, each
    row padded to whole bytes, most significant bit = leftmost pixel."""
    out = bytearray()
    for row in reversed(rows):
        for x0 in range(0, width, 8):
            b = 0
            for i, px in enumerate(row[x0:x0 + 8]):
                if px:
                    b |= 0x80 >> i
            out.append(b)
    return bytes(out)


def build_bitmap_font(handle, ident, directory, filename, unicode_file):
    font = PcfFont(os.path.join(directory, filename))
    uni = PcfFont(os.path.join(directory, unicode_file)) if unicode_file else None
    asc, desc = font.max_bounds[3], font.max_bounds[4]
    glyphs, bits = [], bytearray()
    for code in range(FIRST_CHAR, LAST_BITMAP_CHAR + 1):
        g = font.glyph(code)
        if uni is not None and code in ADOBE_LEGACY_CODES:
            g = uni.glyph(ADOBE_LEGACY_CODES[code])
            if g is None:
                die("%s lacks U+%04X" % (unicode_file, ADOBE_LEGACY_CODES[code]))
        if g is None:
            glyphs.append((0, 0, 0, 0, 0, 0, code))
            continue
        (lb, rb, advance, ascent, descent), rows = g
        width, height = rb - lb, ascent + descent
        if width <= 0 or height <= 0:
            width = height = 0
            rows = []
        data = glbitmap_bytes(rows, width)
        offset = len(bits)
        bits += data
        if not (0 <= width <= 255 and 0 <= height <= 255 and 0 <= advance <= 255
                and -128 <= -lb <= 127 and -128 <= descent <= 127):
            die("%s: glyph %d does not fit the glyph table's types" % (filename, code))
        glyphs.append((width, height, -lb, descent, advance, offset, code))
    if len(bits) > 0xFFFF:
        die("%s: bitmap data too large for 16-bit offsets" % filename)
    return dict(handle=handle, ident=ident, file=os.path.join(directory, filename),
                unicode_file=os.path.join(directory, unicode_file) if unicode_file else None,
                xlfd=GLUT_XLFD[handle], pcf_font=font.props.get("FONT", ""),
                height=asc + desc + 1, glyphs=glyphs, bits=bytes(bits),
                copyright=font.props.get("COPYRIGHT", ""), notice=font.props.get("NOTICE", ""))


# --------------------------------------------------------------------------
# Hershey fonts (.jhf as in hershey-fonts-data)
# --------------------------------------------------------------------------
def load_jhf(path):
    """A .jhf file -> list of (left, right, strokes), one per record in file
    order; points are (x, y) in Hershey units relative to the glyph centre,
    y down.  A record is: 5-column number, 3-column vertex count (including
    the bearing pair), then that many two-character pairs; long records may
    be wrapped over several lines."""
    try:
        with open(path, "rb") as f:
            text = f.read().decode("latin-1")
    except OSError as e:
        die("cannot read %s: %s" % (path, e))
    records, pending = [], ""
    for line in text.split("\n"):
        line = line.rstrip("\r")
        if not line and not pending:
            continue
        pending += line
        need = 8 + 2 * int(pending[5:8])
        if len(pending) >= need:
            records.append(pending[:need])
            pending = ""
    glyphs = []
    for rec in records:
        n = int(rec[5:8])
        body = rec[8:]
        left, right = ord(body[0]) - ord("R"), ord(body[1]) - ord("R")
        strokes, cur = [], []
        for i in range(1, n):
            a, b = body[2 * i], body[2 * i + 1]
            if a == " " and b == "R":  # pen up
                if cur:
                    strokes.append(cur)
                cur = []
            else:
                cur.append((ord(a) - ord("R"), ord(b) - ord("R")))
        if cur:
            strokes.append(cur)
        glyphs.append((left, right, strokes))
    return glyphs


def hershey_glyphs(hershey_dir):
    cache = {}

    def font(name):
        if name not in cache:
            cache[name] = load_jhf(os.path.join(hershey_dir, name))
            if len(cache[name]) != 96:
                die("%s: expected 96 glyphs (32..127), found %d" % (name, len(cache[name])))
        return cache[name]

    out = {}
    for code in range(FIRST_CHAR, LAST_STROKE_CHAR + 1):
        name, src, how = STROKE_SOURCES.get(code, ("rowmans.jhf", code, None))
        left, right, strokes = font(name)[src - FIRST_CHAR]
        if how == "first-stroke":
            s = strokes[0]
            dx = -s[0][0]
            strokes = [[(x + dx, y) for x, y in s]]
            left, right = font("rowmans.jhf")[code - FIRST_CHAR][:2]
        out[code] = (left, right, strokes)
    used = sorted(set(["rowmans.jhf"] + [v[0] for v in STROKE_SOURCES.values()]))
    return out, [os.path.join(hershey_dir, n) for n in used]


def outline_extent(strokes):
    """(segments, xmin, xmax, ymin, ymax) of a Hershey outline in GLUT units,
    y up; x relative to the Hershey glyph centre.  None if it draws nothing."""
    pts = [p for st in strokes for p in st]
    if not pts:
        return None
    s = HERSHEY_SCALE
    xs = [x * s for x, _ in pts]
    ys = [(HERSHEY_BASELINE - y) * s for _, y in pts]
    return sum(len(st) - 1 for st in strokes), min(xs), max(xs), min(ys), max(ys)


def build_stroke_font(glyphs, metrics):
    """glyphs: code -> Hershey (left, right, strokes); metrics: code ->
    (advance, xmin) from the metrics file.  -> [(advance, strips)]."""
    s = HERSHEY_SCALE
    out = []
    for code in range(FIRST_CHAR, LAST_STROKE_CHAR + 1):
        _left, _right, strokes = glyphs[code]
        advance, xmin = metrics[code]
        ext = outline_extent(strokes)
        if ext is None:
            out.append((advance, []))
            continue
        _, hx0, hx1, _, _ = ext
        if code in SHAPE_DIFFERS:
            x0 = advance / 2 - (hx0 + hx1) / 2
        else:
            if xmin is None:
                die("%s: character %d draws nothing in freeglut" % (STROKE_METRICS_FILE, code))
            x0 = xmin - hx0
        strips = [[(x0 + x * s, (HERSHEY_BASELINE - y) * s) for x, y in st] for st in strokes]
        out.append((advance, strips))
    return out


# --------------------------------------------------------------------------
# Stroke font metrics: measured from freeglut, stored in STROKE_METRICS_FILE
# --------------------------------------------------------------------------
# The measuring program.  The viewport (-256, -256, 512, 512) with
# glOrtho(-256, 256, -256, 256, -1, 1) maps object x, y to the same window x, y
# (scalings by powers of two, no offset), so GL_FEEDBACK returns the glyph's
# own coordinates unchanged; the "calibration" line checks that.
MEASURE_C = r"""
#include <GL/freeglut.h>
#include <stdio.h>

static GLfloat buf[1 << 16];

/* Draws with `draw(arg)` in feedback mode; prints the segment count and the
   x, y extent of the line vertices it produced. */
static int feedback(void (*draw)(void*, int), void* font, int c) {
  float x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  int i, n, segs = 0;
  glFeedbackBuffer((GLsizei)(sizeof buf / sizeof buf[0]), GL_3D, buf);
  glRenderMode(GL_FEEDBACK);
  glPushMatrix();
  draw(font, c);
  glPopMatrix();
  n = glRenderMode(GL_RENDER);
  if (n < 0) {
    fprintf(stderr, "feedback buffer overflow\n");
    return 1;
  }
  for (i = 0; i < n;) {
    int token = (int)buf[i++], k;
    if (token == GL_PASS_THROUGH_TOKEN) {
      ++i;
      continue;
    }
    if (token != GL_LINE_TOKEN && token != GL_LINE_RESET_TOKEN) {
      fprintf(stderr, "unexpected feedback token %d\n", token);
      return 1;
    }
    for (k = 0; k < 2; ++k, i += 3) {
      float x = buf[i], y = buf[i + 1];
      if (!segs && !k) x0 = x1 = x, y0 = y1 = y;
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
    }
    ++segs;
  }
  printf(" %d %.9g %.9g %.9g %.9g\n", segs, x0, x1, y0, y1);
  return 0;
}

static void calibration_line(void* font, int c) {
  (void)font, (void)c;
  glBegin(GL_LINES);
  glVertex2f(1.5f, -2.25f);
  glVertex2f(-100.125f, 119.0478f);
  glEnd();
}

static void stroke_character(void* font, int c) { glutStrokeCharacter(font, c); }

int main(int argc, char** argv) {
  void* fonts[2] = {GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN};
  int f, c;
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGB);
  glutInitWindowSize(64, 64);
  glutCreateWindow("measure");
  glViewport(-256, -256, 512, 512);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-256, 256, -256, 256, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  printf("version %d\n", glutGet(GLUT_VERSION));
  printf("calibration");
  if (feedback(calibration_line, 0, 0)) return 1;
  for (f = 0; f < 2; ++f) {
    printf("font %d %.9g\n", f, glutStrokeHeight(fonts[f]));
    for (c = 32; c <= 127; ++c) {
#ifdef HAVE_GLUTSTROKEWIDTHF
      float advance = glutStrokeWidthf(fonts[f], c);
#else
      float advance = (float)glutStrokeWidth(fonts[f], c);
#endif
      printf("glyph %d %.9g %d", c, advance, glutStrokeWidth(fonts[f], c));
      if (feedback(stroke_character, fonts[f], c)) return 1;
    }
  }
  return 0;
}
"""


def f32(v):
    return struct.unpack("<f", struct.pack("<f", v))[0]


def f32_text(v):
    """The shortest decimal that reads back as the same float."""
    for digits in range(1, 10):
        t = "%.*g" % (digits, v)
        if f32(float(t)) == f32(v):
            return t
    return "%.9g" % v


def measure_stroke_metrics(glyphs, path):
    """Builds and runs MEASURE_C against freeglut (under xvfb-run), checks the
    result against the Hershey outlines and writes the metrics file."""
    import shutil
    import tempfile

    for tool, pkg in (("gcc", "gcc"), ("xvfb-run", "xvfb")):
        if not shutil.which(tool):
            die("--measure-stroke-metrics needs %s: apt-get install -y %s" % (tool, pkg))
    headers = ["/usr/include/GL/freeglut_std.h", "/usr/include/GL/freeglut_ext.h"]
    if not os.path.exists(headers[0]):
        die("--measure-stroke-metrics needs freeglut: apt-get install -y freeglut3-dev")
    have_widthf = any("glutStrokeWidthf" in open(h, encoding="latin-1").read()
                      for h in headers if os.path.exists(h))
    with tempfile.TemporaryDirectory(prefix="gen_glut_fonts.") as tmp:
        src, exe = os.path.join(tmp, "measure.c"), os.path.join(tmp, "measure")
        with open(src, "w") as f:
            f.write(MEASURE_C)
        cc = ["gcc", "-std=c99", "-O1", "-Wall", "-o", exe, src, "-lglut", "-lGL"]
        if have_widthf:
            cc.insert(1, "-DHAVE_GLUTSTROKEWIDTHF")
        r = subprocess.run(cc, capture_output=True, text=True)
        if r.returncode != 0:
            die("building the measuring program failed:\n" + r.stderr)
        r = subprocess.run(["xvfb-run", "-a", exe], capture_output=True, text=True)
        if r.returncode != 0:
            die("the measuring program failed (%d):\n%s" % (r.returncode, r.stderr))
    lines = [l.split() for l in r.stdout.splitlines() if l.strip()]

    version, calibration, fonts, font = None, None, [], None
    for p in lines:
        if p[0] == "version":
            version = int(p[1])
        elif p[0] == "calibration":
            calibration = [float(v) for v in p[2:]]
        elif p[0] == "font":
            font = {"height": float(p[2]), "glyphs": {}}
            fonts.append(font)
        elif p[0] == "glyph":
            font["glyphs"][int(p[1])] = (float(p[2]), int(p[3]), int(p[4]),
                                         [float(v) for v in p[5:9]])
    if [f32(v) for v in calibration or []] != [f32(-100.125), f32(1.5), f32(-2.25), f32(119.0478)]:
        die("feedback does not return object coordinates unchanged: %r" % calibration)
    if len(fonts) != len(STROKE_FONTS):
        die("the measuring program's output is incomplete")

    height = (HERSHEY_BOTTOM - HERSHEY_TOP) * HERSHEY_SCALE
    rows, problems, same_shape = [], [], []
    for (_ident, name, handle), font in zip(STROKE_FONTS, fonts):
        if g6(font["height"]) != g6(height):
            problems.append("%s: glutStrokeHeight %g, not %g" % (name, font["height"], height))
        for code in range(FIRST_CHAR, LAST_STROKE_CHAR + 1):
            advance, iadvance, segs, (x0, x1, y0, y1) = font["glyphs"][code]
            if iadvance != int(advance + 0.5):
                problems.append("%s %d: glutStrokeWidth %d is not the rounded advance %g"
                                % (name, code, iadvance, advance))
            ext = outline_extent(glyphs[code][2])
            if ext is None or segs == 0:
                if (ext is None) != (segs == 0):
                    problems.append("%s %d: only one of freeglut and Hershey draws it" % (name, code))
                rows.append((name, code, advance, None))
                continue
            hsegs, hx0, hx1, hy0, hy1 = ext
            tol = 2e-3
            same = (segs == hsegs and abs((x1 - x0) - (hx1 - hx0)) < tol
                    and abs(y0 - hy0) < tol and abs(y1 - hy1) < tol)
            if same and code in SHAPE_DIFFERS:
                same_shape.append("%s %d" % (name, code))
            elif not same and code not in SHAPE_DIFFERS:
                problems.append("%s %d: freeglut draws %d segments in x %g..%g, y %g..%g; "
                                "the Hershey outline %d segments, %g wide, y %g..%g"
                                % (name, code, segs, x0, x1, y0, y1,
                                   hsegs, hx1 - hx0, hy0, hy1))
            rows.append((name, code, advance, x0))
    if same_shape:
        problems.append("SHAPE_DIFFERS lists glyphs freeglut draws like Hershey: "
                        + ", ".join(same_shape))
    if problems:
        die("the measured glyphs do not fit the Hershey outlines:\n  " + "\n  ".join(problems))

    pkgs = package_versions(["libglut3.12", "freeglut3", "libglut-dev", "freeglut3-dev"])
    head = [
        "GLUT stroke font metrics: where GLUT places each glyph, not what it looks",
        "like.  This file holds metrics only (two numbers per glyph); the glyph",
        "outlines are Hershey's (hershey-fonts-data), see scripts/gen_glut_fonts.py,",
        "which reads this file.",
        "",
        "Measured by `python3 scripts/gen_glut_fonts.py --measure-stroke-metrics`",
        "from freeglut through its public API, with a small C program run under",
        "xvfb-run; glutGet(GLUT_VERSION) was %d." % (version or 0),
    ] + textwrap.wrap("Packages: " + (", ".join(pkgs) if pkgs else "(unknown)") + ".", 76) + [
        "For each font and character code c:",
        "  advance  glutStrokeWidthf(font, c)%s" % (
            "" if have_widthf else "  (here glutStrokeWidth: integers)"),
        "  xmin     the smallest x of the vertices glutStrokeCharacter(font, c)",
        "           draws, read back in GL_FEEDBACK mode (GL_3D) with a viewport and",
        "           orthographic projection that map object x, y to window x, y",
        "           unchanged; \"-\" if the glyph draws nothing.",
        "The generator moves each Hershey outline so that its smallest x is xmin;",
        "not '@', '_' and 127, whose GLUT outlines differ from Hershey's: their",
        "Hershey ink is centred in the advance, their xmin is only a record.",
        "Values are single-precision floats, in the shortest decimal form.",
        "",
        "font code advance xmin",
    ]
    out = ["# " + h if h else "#" for h in head]
    for name, code, advance, xmin in rows:
        out.append("%s %d %s %s" % (name, code, f32_text(advance),
                                    "-" if xmin is None else f32_text(xmin)))
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(out) + "\n")
    print("wrote %s" % path)


def read_stroke_metrics(path):
    """-> {font name: {code: (advance, xmin or None)}}"""
    try:
        with open(path, encoding="ascii") as f:
            text = f.read()
    except OSError as e:
        die("cannot read %s: %s (re-measure with --measure-stroke-metrics)" % (path, e))
    out = {name: {} for _, name, _ in STROKE_FONTS}
    for n, line in enumerate(text.split("\n"), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        p = line.split()
        if len(p) != 4 or p[0] not in out:
            die("%s:%d: not 'font code advance xmin'" % (path, n))
        out[p[0]][int(p[1])] = (float(p[2]), None if p[3] == "-" else float(p[3]))
    for name, m in out.items():
        missing = [c for c in range(FIRST_CHAR, LAST_STROKE_CHAR + 1) if c not in m]
        if missing:
            die("%s: %s lacks characters %s" % (path, name, missing))
    return out


# --------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------
def g6(v):
    """A float literal with six significant digits, GLUT's own precision."""
    t = "%g" % v
    if t == "-0":
        t = "0"
    if "." not in t and "e" not in t:
        t += ".0"
    return t + "f"


def doc_section(path, start, stop_prefixes):
    """Lines of a Debian copyright file from the line equal to `start` up to
    (not including) the next line beginning with one of stop_prefixes."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().split("\n")
    except OSError as e:
        die("cannot read %s: %s" % (path, e))
    for i, line in enumerate(lines):
        if line.strip() == start:
            out = []
            for l in lines[i + 1:]:
                if any(l.startswith(p) for p in stop_prefixes):
                    break
                out.append(l.rstrip())
            while out and not out[-1].strip():
                out.pop()
            return out
    die("%s: section %r not found" % (path, start))


def package_versions(names):
    try:
        r = subprocess.run(["dpkg-query", "-W", "-f=${Package} ${Version}\n"] + names,
                           capture_output=True, text=True, check=False)
        return [l for l in r.stdout.splitlines() if l.strip()]
    except OSError:
        return []


def comment_block(lines, indent="// "):
    return "\n".join((indent + l.expandtabs(4)).rstrip() for l in lines)


def hex_string_literal(data, indent="    ", width=96):
    h = data.hex()
    if not h:
        return indent + '""'
    return "\n".join(indent + '"' + h[i:i + width] + '"' for i in range(0, len(h), width))


def emit(bitmap_fonts, stroke_fonts, hershey_files, metrics_file, out_path):
    versions = package_versions(["xfonts-base", "xfonts-75dpi", "hershey-fonts-data"])
    adobe_notice = doc_section(DOC_XFONTS_75DPI, "font-adobe-75dpi:", ["font-"])
    misc_notice = doc_section(DOC_XFONTS_BASE, "font-misc-misc/COPYING:", ["font-"])
    hershey_notice = doc_section(DOC_HERSHEY, "License: hershey-license", ["License:"])
    hershey_files_notice = doc_section(DOC_HERSHEY, "Files: hershey-fonts/*.jhf", ["License:"])

    L = []
    w = L.append
    w("// GENERATED FILE - DO NOT EDIT.")
    w("//")
    w("// Generated by:  python3 scripts/gen_glut_fonts.py")
    w("//   (with the Debian packages xfonts-base, xfonts-75dpi and hershey-fonts-data")
    w("//   installed; the script's docstring says how the data is derived)")
    w("// Glyph data of GLUT's standard fonts for Tessel's GLUT (src/glut/fonts.cpp).")
    w("//")
    w("// Source files (Debian packages):")
    for v in versions:
        w("//   package " + v)
    for f in bitmap_fonts:
        w("//   %s" % f["file"])
        if f["unicode_file"]:
            w("//   %s  (codes 0x27, 0x2D, 0x60: U+2019, U+2212, U+2018)" % f["unicode_file"])
    for h in hershey_files:
        w("//   %s" % h)
    w("// and the stroke fonts' metrics (measured from freeglut):")
    w("//   scripts/%s" % os.path.basename(metrics_file))
    w("//")
    w("// ---------------------------------------------------------------------------")
    w("// Licenses and notices of the source fonts")
    w("// ---------------------------------------------------------------------------")
    w("//")
    w("// GLUT_BITMAP_9_BY_15, GLUT_BITMAP_8_BY_13: X11 misc-fixed fonts")
    w("// (xfonts-base, font-misc-misc), whose notice is:")
    w(comment_block(misc_notice))
    seen = set()
    for f in bitmap_fonts:
        for key in ("copyright", "notice"):
            t = f[key]
            if t and t not in seen and f["handle"] in (2, 3):
                seen.add(t)
                w("//   (%s: %s)" % (key.upper(), t))
    w("//")
    w("// GLUT_BITMAP_TIMES_ROMAN_10/24, GLUT_BITMAP_HELVETICA_10/12/18: Adobe 75dpi")
    w("// fonts (xfonts-75dpi, font-adobe-75dpi).  The fonts' own properties:")
    for f in bitmap_fonts:
        if f["handle"] in (2, 3):
            continue
        w("//   %s" % f["pcf_font"])
        for key in ("copyright", "notice"):
            if f[key].strip():
                for line in textwrap.wrap("%s: %s" % (key.upper(), f[key].strip()), 74):
                    w("//     " + line)
    w("// and the package's copyright notice and permission notice for them:")
    w("//")
    w(comment_block(adobe_notice))
    w("//")
    w("// GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN: from the Hershey fonts")
    w("// (hershey-fonts-data), whose copyright file says of the .jhf files:")
    w("//")
    w(comment_block(["Files: hershey-fonts/*.jhf"] + hershey_files_notice))
    w("//")
    w("// and their license:")
    w("//")
    w(comment_block(hershey_notice))
    w("//")
    w("// As that license requires, the acknowledgements:")
    w("//   - The Hershey Fonts were originally created by Dr. A. V. Hershey while")
    w("//     working at the U. S. National Bureau of Standards.")
    w("//   - The format of the Font data in this distribution was originally")
    w("//     created by James Hurt, Cognition, Inc., 900 Technology Park Drive,")
    w("//     Billerica, MA 01821 (mit-eddie!ci-dandelion!hurt).")
    w("// The data below is a conversion to another format (floating-point line")
    w("// strips), not the NTIS format.")
    w("")
    w('#include "fonts.hpp"')
    w("")
    w("namespace tessel::glut::fontdata {")
    w("")
    w("// ---- Bitmap fonts -----------------------------------------------------------")
    w("// Per glyph: width, height, xorig, yorig, advance, offset of its rows in the")
    w("// font's bits (hex; bottom row first, rows padded to bytes, MSB = leftmost).")
    w("// Absent characters are all zeros.")
    for f in bitmap_fonts:
        name = f["ident"]
        w("")
        w("// %s  (%s)" % (f["xlfd"], os.path.basename(f["file"])))
        w("static const BitmapGlyph k%sGlyphs[%d] = {" % (name, len(f["glyphs"])))
        row = []
        for (gw, gh, xo, yo, adv, off, code) in f["glyphs"]:
            row.append("{%d,%d,%d,%d,%d,%d}" % (gw, gh, xo, yo, adv, off))
            if len(row) == 6:
                w("    " + ",".join(row) + ",")
                row = []
        if row:
            w("    " + ",".join(row) + ",")
        w("};")
        w("static const char k%sBits[] =" % name)
        w(hex_string_literal(f["bits"]) + ";")
    w("")
    w("const BitmapFont kBitmapFonts[kBitmapFontCount] = {")
    for f in bitmap_fonts:
        w('    {"%s", %d, %d, %d, k%sGlyphs, k%sBits, %d},' % (
            f["xlfd"], f["height"], FIRST_CHAR, len(f["glyphs"]), f["ident"], f["ident"],
            len(f["bits"])))
    w("};")
    w("")
    w("// ---- Stroke fonts -----------------------------------------------------------")
    w("// Per glyph: advance, first strip, strip count.  Per strip: first vertex,")
    w("// vertex count.  Vertices: x, y pairs in GLUT units.")
    for ident, name, height, glyphs in stroke_fonts:
        strips, verts, table = [], [], []
        for advance, glyph_strips in glyphs:
            table.append((advance, len(strips), len(glyph_strips)))
            for st in glyph_strips:
                strips.append((len(verts), len(st)))
                verts.extend(st)
        if len(verts) > 0xFFFF or len(strips) > 0xFFFF:
            die("stroke font too large for 16-bit indices")
        w("")
        w("static const StrokeGlyph k%sGlyphs[%d] = {" % (ident, len(table)))
        for i in range(0, len(table), 4):
            w("    " + ",".join("{%s,%d,%d}" % (g6(a), s0, n) for a, s0, n in table[i:i + 4]) + ",")
        w("};")
        w("static const StrokeStrip k%sStrips[%d] = {" % (ident, len(strips)))
        for i in range(0, len(strips), 8):
            w("    " + ",".join("{%d,%d}" % s for s in strips[i:i + 8]) + ",")
        w("};")
        w("static const float k%sVertices[%d] = {" % (ident, 2 * len(verts)))
        for i in range(0, len(verts), 5):
            w("    " + ",".join("%s,%s" % (g6(x), g6(y)) for x, y in verts[i:i + 5]) + ",")
        w("};")
    w("")
    w("const StrokeFont kStrokeFonts[kStrokeFontCount] = {")
    for ident, name, height, glyphs in stroke_fonts:
        w('    {"%s", %s, %d, %d, k%sGlyphs, k%sStrips, k%sVertices},' % (
            name, g6(height), FIRST_CHAR, len(glyphs), ident, ident, ident))
    w("};")
    w("")
    w("}  // namespace tessel::glut::fontdata")
    text = "\n".join(L) + "\n"
    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    with open(out_path, "w", encoding="ascii") as f:
        f.write(text)
    return len(text)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--output", default=os.path.join(root, "src", "glut", "font_data.cpp"))
    ap.add_argument("--hershey-dir", default=HERSHEY_DIR)
    ap.add_argument("--measure-stroke-metrics", action="store_true",
                    help="re-measure scripts/%s from freeglut first" % STROKE_METRICS_FILE)
    args = ap.parse_args()

    for d, pkg in ((XFONTS_MISC, "xfonts-base"), (XFONTS_75DPI, "xfonts-75dpi"),
                   (args.hershey_dir, "hershey-fonts-data")):
        if not os.path.isdir(d):
            die("%s not found: apt-get install -y %s" % (d, pkg))

    glyphs, hershey_files = hershey_glyphs(args.hershey_dir)
    metrics_file = os.path.join(here, STROKE_METRICS_FILE)
    if args.measure_stroke_metrics:
        measure_stroke_metrics(glyphs, metrics_file)
    metrics = read_stroke_metrics(metrics_file)

    bitmap_fonts = [build_bitmap_font(*spec) for spec in BITMAP_FONTS]
    height = (HERSHEY_BOTTOM - HERSHEY_TOP) * HERSHEY_SCALE
    stroke_fonts = [(ident, name, height, build_stroke_font(glyphs, metrics[name]))
                    for ident, name, _handle in STROKE_FONTS]
    size = emit(bitmap_fonts, stroke_fonts, hershey_files, metrics_file, args.output)
    print("wrote %s (%d bytes)" % (args.output, size))


if __name__ == "__main__":
    main()
