// GLUT's font functions on OpenGL 1.x: bitmap fonts through glBitmap, stroke
// fonts as GL_LINE_STRIPs, with the glyph tables of font_data.cpp (generated
// by scripts/gen_glut_fonts.py).  Behaviour follows GLUT 3.7 and freeglut:
// the same glBitmap arguments and pixel-store settings, the same rounding of
// stroke widths, freeglut's newline handling in the string functions.  An
// unknown font handle or a character the font lacks draws nothing and
// measures 0.
#include "fonts.hpp"

#include <GL/glut.h>

#include <array>
#include <cstdint>
#include <vector>

namespace tessel::glut {

namespace {

using fontdata::BitmapFont;
using fontdata::BitmapGlyph;
using fontdata::StrokeFont;
using fontdata::StrokeGlyph;
using fontdata::StrokeStrip;

const BitmapFont* bitmap_font(const void* font) {
  const auto h = reinterpret_cast<std::uintptr_t>(font);
  if (h < std::uintptr_t(fontdata::kFirstBitmapHandle) ||
      h >= std::uintptr_t(fontdata::kFirstBitmapHandle + fontdata::kBitmapFontCount))
    return nullptr;
  return &fontdata::kBitmapFonts[h - fontdata::kFirstBitmapHandle];
}

const StrokeFont* stroke_font(const void* font) {
  const auto h = reinterpret_cast<std::uintptr_t>(font);
  if (h >= std::uintptr_t(fontdata::kStrokeFontCount)) return nullptr;
  return &fontdata::kStrokeFonts[h];
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 0;
}

// The glyph bytes of every bitmap font, decoded from the hex tables once, on
// first use (thread-safe: a function-local static).
const std::uint8_t* font_bits(const BitmapFont& font) {
  static const auto decoded = [] {
    std::array<std::vector<std::uint8_t>, fontdata::kBitmapFontCount> all;
    for (int i = 0; i < fontdata::kBitmapFontCount; ++i) {
      const BitmapFont& f = fontdata::kBitmapFonts[i];
      std::vector<std::uint8_t>& out = all[std::size_t(i)];
      out.resize(f.bit_bytes);
      for (std::size_t k = 0; k < f.bit_bytes; ++k)
        out[k] = std::uint8_t(hex_digit(f.hex_bits[2 * k]) << 4 | hex_digit(f.hex_bits[2 * k + 1]));
    }
    return all;
  }();
  return decoded[std::size_t(&font - fontdata::kBitmapFonts)].data();
}

// The glyph of `character`, or null when the font does not have it.
const BitmapGlyph* bitmap_glyph_of(const BitmapFont& font, int character) {
  if (character < font.first || character >= font.first + font.count) return nullptr;
  const BitmapGlyph& g = font.glyphs[character - font.first];
  if (g.advance == 0 && g.width == 0) return nullptr;
  return &g;
}

const StrokeGlyph* stroke_glyph_of(const StrokeFont& font, int character) {
  if (character < font.first || character >= font.first + font.count) return nullptr;
  return &font.glyphs[character - font.first];
}

void draw_bitmap_glyph(const BitmapFont& font, const BitmapGlyph& g) {
  glBitmap(GLsizei(g.width), GLsizei(g.height), GLfloat(g.xorig), GLfloat(g.yorig), GLfloat(g.advance), 0.0f,
           g.width && g.height ? font_bits(font) + g.offset : nullptr);
}

// The unpack state GLUT draws its glyphs with, the caller's restored after.
class GlyphUnpackState {
 public:
  GlyphUnpackState() {
    for (std::size_t i = 0; i < kNames.size(); ++i) glGetIntegerv(kNames[i], &saved_[i]);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  ~GlyphUnpackState() {
    for (std::size_t i = 0; i < kNames.size(); ++i) glPixelStorei(kNames[i], saved_[i]);
  }
  GlyphUnpackState(const GlyphUnpackState&) = delete;
  GlyphUnpackState& operator=(const GlyphUnpackState&) = delete;

 private:
  static constexpr std::array<GLenum, 6> kNames = {GL_UNPACK_SWAP_BYTES,  GL_UNPACK_LSB_FIRST,
                                                   GL_UNPACK_ROW_LENGTH,  GL_UNPACK_SKIP_ROWS,
                                                   GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT};
  std::array<GLint, 6> saved_{};
};

void draw_stroke_glyph(const StrokeFont& font, const StrokeGlyph& g) {
  for (unsigned s = 0; s < g.count; ++s) {
    const StrokeStrip& strip = font.strips[g.first + s];
    const float* v = font.vertices + 2 * std::size_t(strip.first);
    glBegin(GL_LINE_STRIP);
    for (unsigned k = 0; k < strip.count; ++k) glVertex2f(v[2 * k], v[2 * k + 1]);
    glEnd();
  }
  glTranslatef(g.advance, 0.0f, 0.0f);
}

}  // namespace

bool bitmap_glyph(const void* font, int character, BitmapGlyphView& out) {
  const BitmapFont* f = bitmap_font(font);
  if (!f) return false;
  const BitmapGlyph* g = bitmap_glyph_of(*f, character);
  if (!g) return false;
  out.width = g->width;
  out.height = g->height;
  out.xorig = g->xorig;
  out.yorig = g->yorig;
  out.advance = g->advance;
  out.bits = font_bits(*f) + g->offset;
  return true;
}

}  // namespace tessel::glut

using namespace tessel::glut;

extern "C" {

void TESSEL_APIENTRY glutBitmapCharacter(void* font, int character) {
  const fontdata::BitmapFont* f = bitmap_font(font);
  if (!f) return;
  const fontdata::BitmapGlyph* g = bitmap_glyph_of(*f, character);
  if (!g) return;
  GlyphUnpackState unpack;
  draw_bitmap_glyph(*f, *g);
}

// freeglut: a newline moves the raster position back to where the line began
// and down by the font's height.
void TESSEL_APIENTRY glutBitmapString(void* font, const unsigned char* string) {
  const fontdata::BitmapFont* f = bitmap_font(font);
  if (!f || !string || !*string) return;
  GlyphUnpackState unpack;
  float x = 0.0f;
  for (; *string; ++string) {
    if (*string == '\n') {
      glBitmap(0, 0, 0.0f, 0.0f, -x, -float(f->height), nullptr);
      x = 0.0f;
    } else if (const fontdata::BitmapGlyph* g = bitmap_glyph_of(*f, *string)) {
      draw_bitmap_glyph(*f, *g);
      x += float(g->advance);
    }
  }
}

int TESSEL_APIENTRY glutBitmapWidth(void* font, int character) {
  const fontdata::BitmapFont* f = bitmap_font(font);
  if (!f) return 0;
  const fontdata::BitmapGlyph* g = bitmap_glyph_of(*f, character);
  return g ? int(g->advance) : 0;
}

// The sum of the advances; with newlines (freeglut), the longest line's.
int TESSEL_APIENTRY glutBitmapLength(void* font, const unsigned char* string) {
  const fontdata::BitmapFont* f = bitmap_font(font);
  if (!f || !string) return 0;
  int longest = 0, line = 0;
  for (; *string; ++string) {
    if (*string == '\n') {
      if (line > longest) longest = line;
      line = 0;
    } else if (const fontdata::BitmapGlyph* g = bitmap_glyph_of(*f, *string)) {
      line += g->advance;
    }
  }
  return line > longest ? line : longest;
}

int TESSEL_APIENTRY glutBitmapHeight(void* font) {
  const fontdata::BitmapFont* f = bitmap_font(font);
  return f ? f->height : 0;
}

void TESSEL_APIENTRY glutStrokeCharacter(void* font, int character) {
  const fontdata::StrokeFont* f = stroke_font(font);
  if (!f) return;
  const fontdata::StrokeGlyph* g = stroke_glyph_of(*f, character);
  if (!g) return;
  draw_stroke_glyph(*f, *g);
}

// freeglut: a newline translates back by the line's length and down by the
// font's height.
void TESSEL_APIENTRY glutStrokeString(void* font, const unsigned char* string) {
  const fontdata::StrokeFont* f = stroke_font(font);
  if (!f || !string) return;
  float length = 0.0f;
  for (; *string; ++string) {
    if (*string == '\n') {
      glTranslatef(-length, -f->height, 0.0f);
      length = 0.0f;
    } else if (const fontdata::StrokeGlyph* g = stroke_glyph_of(*f, *string)) {
      draw_stroke_glyph(*f, *g);
      length += g->advance;
    }
  }
}

int TESSEL_APIENTRY glutStrokeWidth(void* font, int character) {
  const fontdata::StrokeFont* f = stroke_font(font);
  if (!f) return 0;
  const fontdata::StrokeGlyph* g = stroke_glyph_of(*f, character);
  return g ? int(g->advance + 0.5f) : 0;
}

// The sum of the advances, rounded; with newlines (freeglut), the longest
// line's.
int TESSEL_APIENTRY glutStrokeLength(void* font, const unsigned char* string) {
  const fontdata::StrokeFont* f = stroke_font(font);
  if (!f || !string) return 0;
  float longest = 0.0f, line = 0.0f;
  for (; *string; ++string) {
    if (*string == '\n') {
      if (line > longest) longest = line;
      line = 0.0f;
    } else if (const fontdata::StrokeGlyph* g = stroke_glyph_of(*f, *string)) {
      line += g->advance;
    }
  }
  return int((line > longest ? line : longest) + 0.5f);
}

GLfloat TESSEL_APIENTRY glutStrokeHeight(void* font) {
  const fontdata::StrokeFont* f = stroke_font(font);
  return f ? f->height : 0.0f;
}

}  // extern "C"
