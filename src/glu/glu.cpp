// Tessel's GLU 1.3: error strings, the matrix helpers, projection, image scaling and mipmap
// building. Everything here is written on top of OpenGL 1.1 entry points only (glGet*,
// glMultMatrix*, glOrtho, glTranslate*, glScale*, glPixelStorei, glTexImage1D/2D), and
// glTexImage3D (GL 1.2) for 3D mipmaps, so it runs unchanged on Tessel's own GL and on any
// other GL implementation.
//
// Section numbers refer to "The OpenGL Graphics System Utility Library, Version 1.3" (GLU 1.3).
// Where the specification leaves the numerics open (rounding, filtering at the image edges) the
// behaviour follows the reference GLU that Mesa ships, so that images agree with it.

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

namespace {

// ---------------------------------------------------------------------------------------------
// Pixel storage (GL 1.1 section 3.6.1): read the caller's modes, set ours, put theirs back.

struct PixelStore {
  GLint alignment = 4, rowLength = 0, skipRows = 0, skipPixels = 0, swapBytes = 0;
};

PixelStore getUnpack() {
  PixelStore s;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &s.alignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &s.rowLength);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &s.skipRows);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &s.skipPixels);
  glGetIntegerv(GL_UNPACK_SWAP_BYTES, &s.swapBytes);
  return s;
}

PixelStore getPack() {
  PixelStore s;
  glGetIntegerv(GL_PACK_ALIGNMENT, &s.alignment);
  glGetIntegerv(GL_PACK_ROW_LENGTH, &s.rowLength);
  glGetIntegerv(GL_PACK_SKIP_ROWS, &s.skipRows);
  glGetIntegerv(GL_PACK_SKIP_PIXELS, &s.skipPixels);
  glGetIntegerv(GL_PACK_SWAP_BYTES, &s.swapBytes);
  return s;
}

void setUnpack(const PixelStore& s) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, s.alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, s.rowLength);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, s.skipRows);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, s.skipPixels);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, s.swapBytes);
}

// Our own buffers are tightly packed: one byte alignment, no skipping, native byte order.
void setTightUnpack() {
  PixelStore tight;
  tight.alignment = 1;
  setUnpack(tight);
}

// Number of components of a pixel format; 0 if GLU does not scale it.
int componentsOf(GLenum format) {
  switch (format) {
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB:
#ifdef GL_BGR
    case GL_BGR:
#endif
      return 3;
    case GL_RGBA:
#ifdef GL_BGRA
    case GL_BGRA:
#endif
      return 4;
    default: return 0;
  }
}

// Bytes per component of a pixel type; 0 if GLU does not scale it.
int sizeOfType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT: return 4;
    default: return 0;
  }
}

bool isPackedType(GLenum type) {
  switch (type) {
#ifdef GL_UNSIGNED_BYTE_3_3_2
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV: return true;
#endif
    default: return false;
  }
}

// Where pixel (x, y) of an image with the given layout starts (GL 1.1 section 3.6.4, "Unpacking").
struct Layout {
  const unsigned char* base = nullptr;
  size_t rowBytes = 0, groupBytes = 0;
  int elementBytes = 0;
  bool swap = false;
};

Layout layoutOf(const void* data, const PixelStore& ps, int width, int components, int elementBytes) {
  Layout l;
  l.elementBytes = elementBytes;
  l.groupBytes = static_cast<size_t>(components) * elementBytes;
  const size_t groupsPerRow =
      ps.rowLength > 0 ? static_cast<size_t>(ps.rowLength) : static_cast<size_t>(width);
  size_t row = groupsPerRow * l.groupBytes;
  const size_t align = ps.alignment > 0 ? static_cast<size_t>(ps.alignment) : 1;
  // Rows start on multiples of the alignment when it exceeds the element size.
  if (static_cast<size_t>(elementBytes) < align) row = (row + align - 1) / align * align;
  l.rowBytes = row;
  l.swap = ps.swapBytes != 0 && elementBytes > 1;
  l.base = static_cast<const unsigned char*>(data) + static_cast<size_t>(ps.skipRows) * row +
           static_cast<size_t>(ps.skipPixels) * l.groupBytes;
  return l;
}

// One element's bits, byte-swapped if asked.
template <class T>
T loadElement(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

template <class T>
void storeElement(unsigned char* p, T v, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  std::memcpy(p, b, sizeof(T));
}

// Reads an element as a double holding its value in the units of its own type.
double readValue(const unsigned char* p, GLenum type, bool swap) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return *p;
    case GL_BYTE: return static_cast<signed char>(*p);
    case GL_UNSIGNED_SHORT: return loadElement<uint16_t>(p, swap);
    case GL_SHORT: return loadElement<int16_t>(p, swap);
    case GL_UNSIGNED_INT: return loadElement<uint32_t>(p, swap);
    case GL_INT: return loadElement<int32_t>(p, swap);
    default: return loadElement<float>(p, swap);
  }
}

// ---------------------------------------------------------------------------------------------
// gluScaleImage works on a 16-bit unsigned intermediate, as the reference GLU does: every input
// type is widened to 0..65535, filtered, and narrowed to the output type.

uint16_t widen16(const unsigned char* p, GLenum type, bool swap) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<uint16_t>(*p * 257);
    case GL_BYTE: return static_cast<uint16_t>(static_cast<signed char>(*p) * 516);
    case GL_UNSIGNED_SHORT: return loadElement<uint16_t>(p, swap);
    case GL_SHORT: return static_cast<uint16_t>(loadElement<int16_t>(p, swap) * 2);
    case GL_UNSIGNED_INT: return static_cast<uint16_t>(loadElement<uint32_t>(p, swap) >> 16);
    case GL_INT: return static_cast<uint16_t>(loadElement<int32_t>(p, swap) >> 15);
    default: {
      const float f = loadElement<float>(p, swap);
      const float scaled = f * 65535.0f;
      // Out-of-range floats saturate instead of invoking undefined conversions.
      if (!(scaled > 0.0f)) return 0;
      if (scaled >= 65535.0f) return 65535;
      return static_cast<uint16_t>(scaled);
    }
  }
}

void narrow16(unsigned char* p, uint16_t v, GLenum type, bool swap) {
  switch (type) {
    case GL_UNSIGNED_BYTE: *p = static_cast<unsigned char>(v >> 8); break;
    case GL_BYTE: *p = static_cast<unsigned char>(static_cast<signed char>(v >> 9)); break;
    case GL_UNSIGNED_SHORT: storeElement<uint16_t>(p, v, swap); break;
    case GL_SHORT: storeElement<int16_t>(p, static_cast<int16_t>(v >> 1), swap); break;
    case GL_UNSIGNED_INT: storeElement<uint32_t>(p, static_cast<uint32_t>(v) * 65537u, swap); break;
    case GL_INT:
      storeElement<int32_t>(p, static_cast<int32_t>((static_cast<uint32_t>(v) * 65537u) >> 1), swap);
      break;
    default: storeElement<float>(p, static_cast<float>(v) / 65535.0f, swap); break;
  }
}

// The box filter of GLU's 16-bit scaling, in three dimensions as the reference GLU's
// scaleInternal3D has it (scale16 below is its one-image case, plus a shortcut for halving): a box around
// each output texel's centre, of one output texel when shrinking and one input texel when magnifying,
// wrapping at the edges, weights and sums in single precision, the mean rounded.
void scale16Volume(int comps, int win, int hin, int din, const uint16_t* in, int wout, int hout, int dout,
                   uint16_t* out) {
  const float convz = static_cast<float>(din) / dout, convy = static_cast<float>(hin) / hout,
              convx = static_cast<float>(win) / wout;
  auto box = [](float centre, float conv, bool shrinking, float& lo, float& hi) {
    if (shrinking) {
      hi = centre + conv / 2;
      lo = centre - conv / 2;
    } else {
      hi = static_cast<float>(centre + 0.5);
      lo = static_cast<float>(centre - 0.5);
    }
  };
  float acc[4];
  for (int od = 0; od < dout; od++) {
    float z0, z1;
    box(static_cast<float>(convz * (od + 0.5)), convz, din > dout, z0, z1);
    for (int oy = 0; oy < hout; oy++) {
      float y0, y1;
      box(static_cast<float>(convy * (oy + 0.5)), convy, hin > hout, y0, y1);
      for (int ox = 0; ox < wout; ox++) {
        float x0, x1;
        box(static_cast<float>(convx * (ox + 0.5)), convx, win > wout, x0, x1);
        for (int k = 0; k < comps; k++) acc[k] = 0.0f;
        float volume = 0.0f;
        float z = z0;
        for (int iz = static_cast<int>(std::floor(z0)); z < z1; iz++, z = static_cast<float>(iz)) {
          const float wz = z1 < static_cast<float>(iz + 1) ? z1 - z : static_cast<float>(iz + 1) - z;
          const int rz = ((iz % din) + din) % din;
          float y = y0;
          for (int iy = static_cast<int>(std::floor(y0)); y < y1; iy++, y = static_cast<float>(iy)) {
            const float wy = y1 < static_cast<float>(iy + 1) ? y1 - y : static_cast<float>(iy + 1) - y;
            const int ry = ((iy % hin) + hin) % hin;
            float x = x0;
            for (int ix = static_cast<int>(std::floor(x0)); x < x1; ix++, x = static_cast<float>(ix)) {
              const float wx = x1 < static_cast<float>(ix + 1) ? x1 - x : static_cast<float>(ix + 1) - x;
              const int rx = ((ix % win) + win) % win;
              const float w = wx * wy * wz;
              volume += w;
              const uint16_t* src = in + ((static_cast<size_t>(rz) * hin + ry) * win + rx) * comps;
              for (int k = 0; k < comps; k++) acc[k] += src[k] * w;
            }
          }
        }
        uint16_t* dst = out + ((static_cast<size_t>(od) * hout + oy) * wout + ox) * comps;
        for (int k = 0; k < comps; k++) {
          const double v = (acc[k] + 0.5) / volume;
          dst[k] = static_cast<uint16_t>(std::clamp(v, 0.0, 65535.0));
        }
      }
    }
  }
}

// Box filter on 16-bit data (GLU 1.3 section 3.1). Each output pixel covers a box of the input
// as wide as one output pixel when shrinking and one input pixel wide when magnifying (which
// interpolates linearly between input pixel centres). Like the reference GLU, boxes that stick
// out of the image wrap around to the opposite edge, the average is rounded to nearest, and
// the arithmetic is single precision (so results agree with it to the last bit).
void scale16(int comps, int win, int hin, const uint16_t* in, int wout, int hout, uint16_t* out) {
  if (win == 2 * wout && hin == 2 * hout) {  // exact halving: average of four, rounded
    for (int y = 0; y < hout; y++)
      for (int x = 0; x < wout; x++)
        for (int k = 0; k < comps; k++) {
          const size_t a = (static_cast<size_t>(2 * y) * win + 2 * x) * comps + k;
          const size_t b = a + static_cast<size_t>(win) * comps;
          const unsigned sum = in[a] + in[a + comps] + in[b] + in[b + comps];
          out[(static_cast<size_t>(y) * wout + x) * comps + k] = static_cast<uint16_t>((sum + 2) / 4);
        }
    return;
  }
  // Otherwise the box filter of scale16Volume on one image (its depth weights are all 1, so
  // the sums and the rounding are the same as a 2D filter's).
  scale16Volume(comps, win, hin, 1, in, wout, hout, 1, out);
}

// Reads a width x height image of the given format/type with the given unpack modes into
// tightly packed 16-bit components.
std::vector<uint16_t> unpack16(const void* data, const PixelStore& ps, int width, int height, int comps,
                               GLenum type) {
  const Layout l = layoutOf(data, ps, width, comps, sizeOfType(type));
  std::vector<uint16_t> out(static_cast<size_t>(width) * height * comps);
  size_t o = 0;
  for (int y = 0; y < height; y++) {
    const unsigned char* row = l.base + static_cast<size_t>(y) * l.rowBytes;
    for (int x = 0; x < width; x++)
      for (int k = 0; k < comps; k++)
        out[o++] = widen16(row + x * l.groupBytes + static_cast<size_t>(k) * l.elementBytes, type, l.swap);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Mipmap filtering in the caller's own type. Values are held as doubles in the units of the
// type (0..255 for GL_UNSIGNED_BYTE and so on), which represents every value exactly.

struct Image {
  int width = 0, height = 0, comps = 0;
  std::vector<double> v;
  double* at(int x, int y) { return v.data() + (static_cast<size_t>(y) * width + x) * comps; }
  const double* at(int x, int y) const { return v.data() + (static_cast<size_t>(y) * width + x) * comps; }
};

Image unpackImage(const void* data, const PixelStore& ps, int width, int height, int comps, GLenum type) {
  Image img;
  img.width = width;
  img.height = height;
  img.comps = comps;
  img.v.resize(static_cast<size_t>(width) * height * comps);
  const Layout l = layoutOf(data, ps, width, comps, sizeOfType(type));
  size_t o = 0;
  for (int y = 0; y < height; y++) {
    const unsigned char* row = l.base + static_cast<size_t>(y) * l.rowBytes;
    for (int x = 0; x < width; x++)
      for (int k = 0; k < comps; k++)
        img.v[o++] =
            readValue(row + x * l.groupBytes + static_cast<size_t>(k) * l.elementBytes, type, l.swap);
  }
  return img;
}

// Integer types keep the result of a division in their own range; C's truncation toward zero
// is what the reference GLU uses for its integer averages.
double truncateFor(GLenum type, double v) { return type == GL_FLOAT ? v : std::trunc(v); }

// Box filter from an arbitrary size to (w, h): every output pixel is the area-weighted average
// of the input region it covers, truncated for integer types (the reference GLU's behaviour
// when it brings an image to power-of-two size). The weights are exact: region edges fall on
// multiples of 1/(w*h) and all arithmetic is done on integers scaled by w and h.
Image boxScale(const Image& in, int w, int h, GLenum type) {
  Image out;
  out.width = w;
  out.height = h;
  out.comps = in.comps;
  out.v.assign(static_cast<size_t>(w) * h * in.comps, 0.0);
  const long long win = in.width, hin = in.height;
  const double area = static_cast<double>(win) * static_cast<double>(hin);
  std::vector<double> acc(static_cast<size_t>(in.comps));
  for (int oy = 0; oy < h; oy++) {
    // The region [oy*hin, (oy+1)*hin) in units of 1/h of an input row.
    const long long ry0 = oy * hin, ry1 = (oy + 1) * hin;
    for (int ox = 0; ox < w; ox++) {
      const long long rx0 = ox * win, rx1 = (ox + 1) * win;
      std::fill(acc.begin(), acc.end(), 0.0);
      for (long long iy = ry0 / h; iy * h < ry1 && iy < hin; iy++) {
        const long long wy = std::min(ry1, (iy + 1) * h) - std::max(ry0, iy * h);
        for (long long ix = rx0 / w; ix * w < rx1 && ix < win; ix++) {
          const long long wx = std::min(rx1, (ix + 1) * w) - std::max(rx0, ix * w);
          const double weight = static_cast<double>(wx * wy);
          const double* src = in.at(static_cast<int>(ix), static_cast<int>(iy));
          for (int k = 0; k < in.comps; k++) acc[k] += src[k] * weight;
        }
      }
      // Weights sum to win*hin (the region is w*h times an output pixel's share of the input).
      double* dst = out.at(ox, oy);
      for (int k = 0; k < in.comps; k++) dst[k] = truncateFor(type, acc[k] / area);
    }
  }
  return out;
}

// One mipmap step (GL 1.1 section 3.8.1): each dimension larger than one is halved; the new
// pixel is the mean of the 2 or 4 pixels it replaces. For integer types the reference GLU
// rounds the mean of four half up but truncates the mean of two (once the image is one pixel
// wide or high); this does the same.
Image halve(const Image& in, GLenum type) {
  Image out;
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.comps = in.comps;
  out.v.resize(static_cast<size_t>(out.width) * out.height * out.comps);
  const int sx = in.width > 1 ? 2 : 1, sy = in.height > 1 ? 2 : 1;
  const int n = sx * sy;
  for (int y = 0; y < out.height; y++)
    for (int x = 0; x < out.width; x++)
      for (int k = 0; k < in.comps; k++) {
        double sum = 0;
        for (int j = 0; j < sy; j++)
          for (int i = 0; i < sx; i++) sum += in.at(x * sx + i, y * sy + j)[k];
        out.at(x, y)[k] = type == GL_FLOAT ? sum / n : std::trunc((n == 4 ? sum + 2 : sum) / n);
      }
  return out;
}

// Packs an image tightly in the given type, for glTexImage with an alignment of 1.
std::vector<unsigned char> packImage(const Image& img, GLenum type) {
  const int es = sizeOfType(type);
  std::vector<unsigned char> out(img.v.size() * es);
  for (size_t i = 0; i < img.v.size(); i++) {
    unsigned char* p = out.data() + i * es;
    const double v = img.v[i];
    switch (type) {
      case GL_UNSIGNED_BYTE: *p = static_cast<unsigned char>(std::clamp(v, 0.0, 255.0)); break;
      case GL_BYTE:
        *p = static_cast<unsigned char>(static_cast<signed char>(std::clamp(v, -128.0, 127.0)));
        break;
      case GL_UNSIGNED_SHORT:
        storeElement<uint16_t>(p, static_cast<uint16_t>(std::clamp(v, 0.0, 65535.0)), false);
        break;
      case GL_SHORT:
        storeElement<int16_t>(p, static_cast<int16_t>(std::clamp(v, -32768.0, 32767.0)), false);
        break;
      case GL_UNSIGNED_INT:
        storeElement<uint32_t>(p, static_cast<uint32_t>(std::clamp(v, 0.0, 4294967295.0)), false);
        break;
      case GL_INT:
        storeElement<int32_t>(p, static_cast<int32_t>(std::clamp(v, -2147483648.0, 2147483647.0)), false);
        break;
      default: storeElement<float>(p, static_cast<float>(v), false); break;
    }
  }
  return out;
}

// The power of two GLU scales a size to: values in [3*2^k, 4*2^k) go up to 4*2^k, the rest
// down to the power of two below them.
int nearestPower(int value) {
  int p = 1;
  while (true) {
    if (value == 1) return p;
    if (value == 3) return p * 4;
    value >>= 1;
    p *= 2;
  }
}

// log2 of a power of two; -1 for anything else.
int log2Exact(int value) {
  if (value <= 0) return -1;
  int i = 0;
  while ((value & 1) == 0) {
    value >>= 1;
    i++;
  }
  return value == 1 ? i : -1;
}

int floorLog2(int value) {
  int i = 0;
  while (value > 1) {
    value >>= 1;
    i++;
  }
  return i;
}

GLint checkMipmapArgs(GLenum format, GLenum type) {
  if (isPackedType(type)) return GLU_INVALID_ENUM;  // not supported by this GLU
  if (componentsOf(format) == 0 || sizeOfType(type) == 0) return GLU_INVALID_ENUM;
  return 0;
}

// Sizes no larger than GL_MAX_TEXTURE_SIZE (GLU 1.3 section 3.2).
void closestFit(int width, int height, int* newWidth, int* newHeight) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (maxSize < 1) maxSize = 64;  // GL 1.1 guarantees at least 64
  *newWidth = std::min(nearestPower(width), static_cast<int>(maxSize));
  *newHeight = std::min(nearestPower(height), static_cast<int>(maxSize));
}

// Builds levels userLevel.. of a 2D mipmap from data of size (width, height), first scaled to
// (newWidth, newHeight), uploading those in [baseLevel, maxLevel].
GLint build2DCore(GLenum target, GLint internalFormat, int width, int height, int newWidth, int newHeight,
                  GLenum format, GLenum type, GLint userLevel, GLint baseLevel, GLint maxLevel,
                  const void* data) {
  const int comps = componentsOf(format);
  const PixelStore saved = getUnpack();
  Image img;
  try {
    img = unpackImage(data, saved, width, height, comps, type);
    if (width != newWidth || height != newHeight) img = boxScale(img, newWidth, newHeight, type);
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  const int levels = std::max(floorLog2(newWidth), floorLog2(newHeight));
  setTightUnpack();
  GLint result = 0;
  try {
    for (int level = userLevel; level <= userLevel + levels; level++) {
      if (level > userLevel) img = halve(img, type);
      if (baseLevel <= level && level <= maxLevel) {
        const std::vector<unsigned char> bytes = packImage(img, type);
        glTexImage2D(target, level, internalFormat, img.width, img.height, 0, format, type, bytes.data());
      }
    }
  } catch (const std::bad_alloc&) {
    result = GLU_OUT_OF_MEMORY;
  }
  setUnpack(saved);
  return result;
}

// 1D mipmaps go through the 16-bit intermediate and are uploaded as GL_UNSIGNED_SHORT, as the
// reference GLU does.
GLint build1DCore(GLenum target, GLint internalFormat, int width, int newWidth, GLenum format, GLenum type,
                  GLint userLevel, GLint baseLevel, GLint maxLevel, const void* data) {
  const int comps = componentsOf(format);
  const PixelStore saved = getUnpack();
  std::vector<uint16_t> cur, next;
  int curWidth = width;
  try {
    cur = unpack16(data, saved, width, 1, comps, type);
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  const int levels = floorLog2(newWidth);
  setTightUnpack();
  GLint result = 0;
  try {
    int levelWidth = newWidth;
    for (int level = userLevel; level <= userLevel + levels; level++) {
      if (curWidth != levelWidth) {
        next.assign(static_cast<size_t>(levelWidth) * comps, 0);
        scale16(comps, curWidth, 1, cur.data(), levelWidth, 1, next.data());
        cur.swap(next);
        curWidth = levelWidth;
      }
      if (baseLevel <= level && level <= maxLevel)
        glTexImage1D(target, level, internalFormat, curWidth, 0, format, GL_UNSIGNED_SHORT, cur.data());
      if (levelWidth > 1) levelWidth /= 2;
    }
  } catch (const std::bad_alloc&) {
    result = GLU_OUT_OF_MEMORY;
  }
  setUnpack(saved);
  return result;
}

// --- 3D mipmaps (GLU 1.3 section 3.2) -------------------------------------------------------
struct Volume {
  int width = 0, height = 0, depth = 0, comps = 0;
  std::vector<double> v;
  double* at(int x, int y, int z) {
    return v.data() + ((static_cast<size_t>(z) * height + y) * width + x) * comps;
  }
  const double* at(int x, int y, int z) const {
    return v.data() + ((static_cast<size_t>(z) * height + y) * width + x) * comps;
  }
};

// The images of a 3D block as GL 1.2 section 3.8.1 unpacks them: image z starts
// (skipImages + z) image heights of rows after the first row.
Volume unpackVolume(const void* data, const PixelStore& ps, GLint imageHeight, GLint skipImages, int width,
                    int height, int depth, int comps, GLenum type) {
  Volume vol;
  vol.width = width;
  vol.height = height;
  vol.depth = depth;
  vol.comps = comps;
  vol.v.resize(static_cast<size_t>(width) * height * depth * comps);
  const Layout l = layoutOf(data, ps, width, comps, sizeOfType(type));
  const size_t imageBytes = l.rowBytes * static_cast<size_t>(imageHeight > 0 ? imageHeight : height);
  size_t o = 0;
  for (int z = 0; z < depth; z++)
    for (int y = 0; y < height; y++) {
      const unsigned char* row =
          l.base + (static_cast<size_t>(skipImages) + z) * imageBytes + static_cast<size_t>(y) * l.rowBytes;
      for (int x = 0; x < width; x++)
        for (int k = 0; k < comps; k++)
          vol.v[o++] =
              readValue(row + x * l.groupBytes + static_cast<size_t>(k) * l.elementBytes, type, l.swap);
    }
  return vol;
}

// One 3D mipmap step: each dimension larger than one is halved; the new texel is the mean of
// the 2, 4 or 8 it replaces, truncated for integer types (the reference GLU's 3D averages
// go through a double and its conversion back). A volume given with depth 1 is halved as an
// image (`image`: the mean of four rounded, as halve() does).
Volume halveVolume(const Volume& in, GLenum type, bool image) {
  Volume out;
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.depth = std::max(1, in.depth / 2);
  out.comps = in.comps;
  out.v.resize(static_cast<size_t>(out.width) * out.height * out.depth * out.comps);
  const int sx = in.width > 1 ? 2 : 1, sy = in.height > 1 ? 2 : 1, sz = in.depth > 1 ? 2 : 1;
  const int n = sx * sy * sz;
  for (int z = 0; z < out.depth; z++)
    for (int y = 0; y < out.height; y++)
      for (int x = 0; x < out.width; x++)
        for (int k = 0; k < in.comps; k++) {
          double sum = 0;
          for (int c = 0; c < sz; c++)
            for (int j = 0; j < sy; j++)
              for (int i = 0; i < sx; i++) sum += in.at(x * sx + i, y * sy + j, z * sz + c)[k];
          out.at(x, y, z)[k] = type == GL_FLOAT ? sum / n : std::trunc((image && n == 4 ? sum + 2 : sum) / n);
        }
  return out;
}

// Builds levels userLevel.. of a 3D mipmap from data of (width, height, depth), first scaled to
// (newWidth, newHeight, newDepth), uploading those in [baseLevel, maxLevel].
GLint build3DCore(GLenum target, GLint internalFormat, int width, int height, int depth, int newWidth,
                  int newHeight, int newDepth, GLenum format, GLenum type, GLint userLevel, GLint baseLevel,
                  GLint maxLevel, const void* data) {
  const int comps = componentsOf(format);
  const PixelStore saved = getUnpack();
  GLint imageHeight = 0, skipImages = 0;
  glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &imageHeight);
  glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &skipImages);
  Volume vol;
  try {
    if (width == newWidth && height == newHeight && depth == newDepth) {
      vol = unpackVolume(data, saved, imageHeight, skipImages, width, height, depth, comps, type);
    } else {
      // Scaled through the 16-bit intermediate, as gluScaleImage does, and back to the type.
      const Layout l = layoutOf(data, saved, width, comps, sizeOfType(type));
      const size_t imageBytes = l.rowBytes * static_cast<size_t>(imageHeight > 0 ? imageHeight : height);
      std::vector<uint16_t> in16;
      for (int z = 0; z < depth; z++) {
        const unsigned char* image =
            static_cast<const unsigned char*>(data) + (static_cast<size_t>(skipImages) + z) * imageBytes;
        const std::vector<uint16_t> one = unpack16(image, saved, width, height, comps, type);
        in16.insert(in16.end(), one.begin(), one.end());
      }
      std::vector<uint16_t> out16(static_cast<size_t>(newWidth) * newHeight * newDepth * comps);
      scale16Volume(comps, width, height, depth, in16.data(), newWidth, newHeight, newDepth, out16.data());
      vol.width = newWidth;
      vol.height = newHeight;
      vol.depth = newDepth;
      vol.comps = comps;
      vol.v.resize(out16.size());
      unsigned char element[4];
      for (size_t i = 0; i < out16.size(); i++) {
        narrow16(element, out16[i], type, false);
        vol.v[i] = readValue(element, type, false);
      }
    }
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  const int levels = std::max({floorLog2(newWidth), floorLog2(newHeight), floorLog2(newDepth)});
  setTightUnpack();
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  GLint result = 0;
  try {
    for (int level = userLevel; level <= userLevel + levels; level++) {
      if (level > userLevel) vol = halveVolume(vol, type, depth == 1);
      if (baseLevel <= level && level <= maxLevel) {
        Image flat;  // the volume's values, for packImage
        flat.v = vol.v;
        const std::vector<unsigned char> bytes = packImage(flat, type);
        glTexImage3D(target, level, internalFormat, vol.width, vol.height, vol.depth, 0, format, type,
                     bytes.data());
      }
    }
  } catch (const std::bad_alloc&) {
    result = GLU_OUT_OF_MEMORY;
  }
  setUnpack(saved);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, imageHeight);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, skipImages);
  return result;
}

bool legalLevels(GLint userLevel, GLint baseLevel, GLint maxLevel, GLint totalLevels) {
  return !(baseLevel < 0 || baseLevel < userLevel || maxLevel < baseLevel || totalLevels < maxLevel);
}

// ---------------------------------------------------------------------------------------------
// Matrices are column-major arrays of 16 doubles, as glGetDoublev returns them.

// r = a * b
void multiply(const double a[16], const double b[16], double r[16]) {
  double t[16];
  for (int c = 0; c < 4; c++)
    for (int row = 0; row < 4; row++) {
      double s = 0;
      for (int k = 0; k < 4; k++) s += a[k * 4 + row] * b[c * 4 + k];
      t[c * 4 + row] = s;
    }
  std::memcpy(r, t, sizeof t);
}

// out = m * v
void transform(const double m[16], const double v[4], double out[4]) {
  for (int row = 0; row < 4; row++)
    out[row] = m[row] * v[0] + m[4 + row] * v[1] + m[8 + row] * v[2] + m[12 + row] * v[3];
}

// Inverse by cofactors (adjugate over determinant); false if singular.
bool invert(const double m[16], double inv[16]) {
  // 2x2 minors of the top two rows and of the bottom two rows.
  const double a0 = m[0] * m[5] - m[4] * m[1], a1 = m[0] * m[9] - m[8] * m[1],
               a2 = m[0] * m[13] - m[12] * m[1];
  const double a3 = m[4] * m[9] - m[8] * m[5], a4 = m[4] * m[13] - m[12] * m[5],
               a5 = m[8] * m[13] - m[12] * m[9];
  const double b0 = m[2] * m[7] - m[6] * m[3], b1 = m[2] * m[11] - m[10] * m[3],
               b2 = m[2] * m[15] - m[14] * m[3];
  const double b3 = m[6] * m[11] - m[10] * m[7], b4 = m[6] * m[15] - m[14] * m[7],
               b5 = m[10] * m[15] - m[14] * m[11];
  const double det = a0 * b5 - a1 * b4 + a2 * b3 + a3 * b2 - a4 * b1 + a5 * b0;
  if (det == 0.0) return false;
  const double d = 1.0 / det;
  double r[16];
  r[0] = (m[5] * b5 - m[9] * b4 + m[13] * b3) * d;
  r[4] = (-m[4] * b5 + m[8] * b4 - m[12] * b3) * d;
  r[8] = (m[7] * a5 - m[11] * a4 + m[15] * a3) * d;
  r[12] = (-m[6] * a5 + m[10] * a4 - m[14] * a3) * d;
  r[1] = (-m[1] * b5 + m[9] * b2 - m[13] * b1) * d;
  r[5] = (m[0] * b5 - m[8] * b2 + m[12] * b1) * d;
  r[9] = (-m[3] * a5 + m[11] * a2 - m[15] * a1) * d;
  r[13] = (m[2] * a5 - m[10] * a2 + m[14] * a1) * d;
  r[2] = (m[1] * b4 - m[5] * b2 + m[13] * b0) * d;
  r[6] = (-m[0] * b4 + m[4] * b2 - m[12] * b0) * d;
  r[10] = (m[3] * a4 - m[7] * a2 + m[15] * a0) * d;
  r[14] = (-m[2] * a4 + m[6] * a2 - m[14] * a0) * d;
  r[3] = (-m[1] * b3 + m[5] * b1 - m[9] * b0) * d;
  r[7] = (m[0] * b3 - m[4] * b1 + m[8] * b0) * d;
  r[11] = (-m[3] * a3 + m[7] * a1 - m[11] * a0) * d;
  r[15] = (m[2] * a3 - m[6] * a1 + m[10] * a0) * d;
  std::memcpy(inv, r, sizeof r);
  return true;
}

void normalize3(float v[3]) {
  const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (len == 0.0f) return;
  v[0] /= len;
  v[1] /= len;
  v[2] /= len;
}

void cross3(const float a[3], const float b[3], float r[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

constexpr double kPi = 3.14159265358979323846;

const GLubyte* str(const char* s) { return reinterpret_cast<const GLubyte*>(s); }

}  // namespace

extern "C" {

// ---------------------------------------------------------------------------------------------
// GLU 1.3 section 2: initialization and errors.

const GLubyte* GLAPIENTRY gluErrorString(GLenum error) {
  switch (error) {
    case GL_NO_ERROR: return str("no error");
    case GL_INVALID_ENUM: return str("invalid enumerant");
    case GL_INVALID_VALUE: return str("invalid value");
    case GL_INVALID_OPERATION: return str("invalid operation");
    case GL_STACK_OVERFLOW: return str("stack overflow");
    case GL_STACK_UNDERFLOW: return str("stack underflow");
    case GL_OUT_OF_MEMORY: return str("out of memory");
    case 0x0506: return str("invalid framebuffer operation");  // GL_INVALID_FRAMEBUFFER_OPERATION
    case 0x8031: return str("table too large");                // GL_TABLE_TOO_LARGE
    case GLU_INVALID_ENUM: return str("invalid enumerant");
    case GLU_INVALID_VALUE: return str("invalid value");
    case GLU_OUT_OF_MEMORY: return str("out of memory");
    case GLU_INCOMPATIBLE_GL_VERSION: return str("incompatible gl version");
    case GLU_INVALID_OPERATION: return str("invalid operation");
    default: break;
  }
  // Tessellator errors (GLU 1.3 section 5.7).
  static const char* const tess[] = {
      "gluTessBeginPolygon() must precede a gluTessEndPolygon()",
      "gluTessBeginContour() must precede a gluTessEndContour()",
      "gluTessEndPolygon() must follow a gluTessBeginPolygon()",
      "gluTessEndContour() must follow a gluTessBeginContour()",
      "a coordinate is too large",
      "need combine callback",
  };
  if (error >= GLU_TESS_ERROR1 && error < GLU_TESS_ERROR1 + 6) return str(tess[error - GLU_TESS_ERROR1]);
  // NURBS errors (GLU 1.3 section 7.6).
  static const char* const nurbs[] = {
      "spline order un-supported",
      "too few knots",
      "valid knot range is empty",
      "decreasing knot sequence knot",
      "knot multiplicity greater than order of spline",
      "gluEndCurve() must follow gluBeginCurve()",
      "gluBeginCurve() must precede gluEndCurve()",
      "missing or extra geometric data",
      "can't draw piecewise linear trimming curves",
      "missing or extra domain data",
      "missing or extra domain data",
      "gluEndTrim() must precede gluEndSurface()",
      "gluBeginSurface() must precede gluEndSurface()",
      "curve of improper type passed as trim curve",
      "gluBeginSurface() must precede gluBeginTrim()",
      "gluEndTrim() must follow gluBeginTrim()",
      "gluBeginTrim() must precede gluEndTrim()",
      "invalid or missing trim curve",
      "gluBeginTrim() must precede gluPwlCurve()",
      "piecewise linear trimming curve referenced twice",
      "piecewise linear trimming curve and nurbs curve mixed",
      "improper usage of trim data type",
      "nurbs curve referenced twice",
      "nurbs curve and piecewise linear trimming curve mixed",
      "nurbs surface referenced twice",
      "invalid property",
      "gluEndSurface() must follow gluBeginSurface()",
      "intersecting or misoriented trim curves",
      "intersecting trim curves",
      "UNUSED",
      "unconnected trim curves",
      "unknown knot error",
      "negative vertex count encountered",
      "negative byte-stride encounteed",
      "unknown type descriptor",
      "null control point reference",
      "duplicate point on piecewise linear trimming curve",
  };
  if (error >= GLU_NURBS_ERROR1 && error <= GLU_NURBS_ERROR37) return str(nurbs[error - GLU_NURBS_ERROR1]);
  return nullptr;
}

const GLubyte* GLAPIENTRY gluGetString(GLenum name) {
  switch (name) {
    case GLU_VERSION: return str("1.3");
    case GLU_EXTENSIONS: return str("");
    default: return nullptr;
  }
}

// GLU 1.3 section 2.2: true if extName is one of the space-separated names in extString.
GLboolean GLAPIENTRY gluCheckExtension(const GLubyte* extName, const GLubyte* extString) {
  if (extName == nullptr || extString == nullptr) return GL_FALSE;
  const char* name = reinterpret_cast<const char*>(extName);
  const size_t len = std::strlen(name);
  if (len == 0 || std::strchr(name, ' ') != nullptr) return GL_FALSE;
  const char* p = reinterpret_cast<const char*>(extString);
  while (*p) {
    while (*p == ' ') p++;
    const char* end = p;
    while (*end && *end != ' ') end++;
    if (static_cast<size_t>(end - p) == len && std::strncmp(p, name, len) == 0) return GL_TRUE;
    p = end;
  }
  return GL_FALSE;
}

// ---------------------------------------------------------------------------------------------
// GLU 1.3 section 4: matrix manipulation.

void GLAPIENTRY gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top) {
  glOrtho(left, right, bottom, top, -1.0, 1.0);
}

// Section 4.1: the projection of glFrustum with a symmetric view volume.
void GLAPIENTRY gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) {
  const double half = fovy / 2 * kPi / 180;
  const double depth = zFar - zNear;
  const double s = std::sin(half);
  if (depth == 0 || s == 0 || aspect == 0) return;
  const double f = std::cos(half) / s;  // cotangent of half the field of view
  GLdouble m[16] = {0};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = -(zFar + zNear) / depth;
  m[11] = -1;
  m[14] = -2 * zNear * zFar / depth;
  glMultMatrixd(m);
}

// Section 4.2: a projection restricted to a delX x delY window around (x, y).
void GLAPIENTRY gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint* viewport) {
  if (delX <= 0 || delY <= 0) return;
  glTranslatef(static_cast<GLfloat>((viewport[2] - 2 * (x - viewport[0])) / delX),
               static_cast<GLfloat>((viewport[3] - 2 * (y - viewport[1])) / delY), 0.0f);
  glScalef(static_cast<GLfloat>(viewport[2] / delX), static_cast<GLfloat>(viewport[3] / delY), 1.0f);
}

// Section 4.3: the viewing transform. Single precision, like the reference GLU, so that the
// matrices (and so the images) agree with it bit for bit.
void GLAPIENTRY gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY,
                          GLdouble centerZ, GLdouble upX, GLdouble upY, GLdouble upZ) {
  float f[3] = {static_cast<float>(centerX - eyeX), static_cast<float>(centerY - eyeY),
                static_cast<float>(centerZ - eyeZ)};
  float up[3] = {static_cast<float>(upX), static_cast<float>(upY), static_cast<float>(upZ)};
  normalize3(f);
  float s[3], u[3];
  cross3(f, up, s);
  normalize3(s);
  cross3(s, f, u);
  // Rows s, u, -f (column-major storage).
  const GLfloat m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, 0, 0, 0, 1};
  glMultMatrixf(m);
  glTranslated(-eyeX, -eyeY, -eyeZ);
}

// Section 4.4: object to window coordinates.
GLint GLAPIENTRY gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble* model,
                            const GLdouble* proj, const GLint* view, GLdouble* winX, GLdouble* winY,
                            GLdouble* winZ) {
  const double obj[4] = {objX, objY, objZ, 1.0};
  double eye[4], clip[4];
  transform(model, obj, eye);
  transform(proj, eye, clip);
  if (clip[3] == 0.0) return GL_FALSE;
  const double nx = clip[0] / clip[3], ny = clip[1] / clip[3], nz = clip[2] / clip[3];
  *winX = view[0] + (nx * 0.5 + 0.5) * view[2];
  *winY = view[1] + (ny * 0.5 + 0.5) * view[3];
  *winZ = nz * 0.5 + 0.5;
  return GL_TRUE;
}

// Section 4.4: window to object coordinates (depth range [0, 1]).
GLint GLAPIENTRY gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble* model,
                              const GLdouble* proj, const GLint* view, GLdouble* objX, GLdouble* objY,
                              GLdouble* objZ) {
  double pm[16], inv[16];
  multiply(proj, model, pm);
  if (!invert(pm, inv)) return GL_FALSE;
  const double ndc[4] = {(winX - view[0]) / view[2] * 2 - 1, (winY - view[1]) / view[3] * 2 - 1, winZ * 2 - 1,
                         1.0};
  double o[4];
  transform(inv, ndc, o);
  if (o[3] == 0.0) return GL_FALSE;
  *objX = o[0] / o[3];
  *objY = o[1] / o[3];
  *objZ = o[2] / o[3];
  return GL_TRUE;
}

// Section 4.4: the same for a given clip w and depth range; the result is not divided by w.
GLint GLAPIENTRY gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW,
                               const GLdouble* model, const GLdouble* proj, const GLint* view,
                               GLdouble nearVal, GLdouble farVal, GLdouble* objX, GLdouble* objY,
                               GLdouble* objZ, GLdouble* objW) {
  double pm[16], inv[16];
  multiply(proj, model, pm);
  if (!invert(pm, inv)) return GL_FALSE;
  const double ndc[4] = {(winX - view[0]) / view[2] * 2 - 1, (winY - view[1]) / view[3] * 2 - 1,
                         (winZ - nearVal) / (farVal - nearVal) * 2 - 1, clipW};
  double o[4];
  transform(inv, ndc, o);
  if (o[3] == 0.0) return GL_FALSE;
  *objX = o[0];
  *objY = o[1];
  *objZ = o[2];
  *objW = o[3];
  return GL_TRUE;
}

// ---------------------------------------------------------------------------------------------
// GLU 1.3 section 3: mipmapping.

// Section 3.1.
GLint GLAPIENTRY gluScaleImage(GLenum format, GLsizei wIn, GLsizei hIn, GLenum typeIn, const void* dataIn,
                               GLsizei wOut, GLsizei hOut, GLenum typeOut, GLvoid* dataOut) {
  if (wIn == 0 || hIn == 0 || wOut == 0 || hOut == 0) return 0;
  if (wIn < 0 || hIn < 0 || wOut < 0 || hOut < 0) return GLU_INVALID_VALUE;
  const int comps = componentsOf(format);
  if (comps == 0 || sizeOfType(typeIn) == 0 || sizeOfType(typeOut) == 0 || isPackedType(typeIn) ||
      isPackedType(typeOut))
    return GLU_INVALID_ENUM;
  try {
    const std::vector<uint16_t> in = unpack16(dataIn, getUnpack(), wIn, hIn, comps, typeIn);
    std::vector<uint16_t> out(static_cast<size_t>(wOut) * hOut * comps);
    scale16(comps, wIn, hIn, in.data(), wOut, hOut, out.data());
    const PixelStore pack = getPack();
    Layout l = layoutOf(dataOut, pack, wOut, comps, sizeOfType(typeOut));
    unsigned char* base = const_cast<unsigned char*>(l.base);
    size_t i = 0;
    for (int y = 0; y < hOut; y++) {
      unsigned char* row = base + static_cast<size_t>(y) * l.rowBytes;
      for (int x = 0; x < wOut; x++)
        for (int k = 0; k < comps; k++)
          narrow16(row + x * l.groupBytes + static_cast<size_t>(k) * l.elementBytes, out[i++], typeOut,
                   l.swap);
    }
  } catch (const std::bad_alloc&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
}

// Section 3.2.
GLint GLAPIENTRY gluBuild1DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width, GLenum format,
                                        GLenum type, GLint level, GLint base, GLint max, const void* data) {
  if (const GLint rc = checkMipmapArgs(format, type)) return rc;
  if (width < 1) return GLU_INVALID_VALUE;
  const int levels = log2Exact(width) + level;
  if (!legalLevels(level, base, max, levels)) return GLU_INVALID_VALUE;
  return build1DCore(target, internalFormat, width, width, format, type, level, base, max, data);
}

GLint GLAPIENTRY gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLenum format,
                                   GLenum type, const void* data) {
  if (const GLint rc = checkMipmapArgs(format, type)) return rc;
  if (width < 1) return GLU_INVALID_VALUE;
  int newWidth = 0, newHeight = 0;
  closestFit(width, 1, &newWidth, &newHeight);
  const int levels = floorLog2(newWidth);
  return build1DCore(target, internalFormat, width, newWidth, format, type, 0, 0, levels, data);
}

GLint GLAPIENTRY gluBuild2DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                        GLenum format, GLenum type, GLint level, GLint base, GLint max,
                                        const void* data) {
  if (const GLint rc = checkMipmapArgs(format, type)) return rc;
  if (width < 1 || height < 1) return GLU_INVALID_VALUE;
  const int levels = std::max(log2Exact(width), log2Exact(height)) + level;
  if (!legalLevels(level, base, max, levels)) return GLU_INVALID_VALUE;
  return build2DCore(target, internalFormat, width, height, width, height, format, type, level, base, max,
                     data);
}

GLint GLAPIENTRY gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                   GLenum format, GLenum type, const void* data) {
  if (const GLint rc = checkMipmapArgs(format, type)) return rc;
  if (width < 1 || height < 1) return GLU_INVALID_VALUE;
  int newWidth = 0, newHeight = 0;
  closestFit(width, height, &newWidth, &newHeight);
  const int levels = std::max(floorLog2(newWidth), floorLog2(newHeight));
  return build2DCore(target, internalFormat, width, height, newWidth, newHeight, format, type, 0, 0, levels,
                     data);
}

GLint GLAPIENTRY gluBuild3DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                        GLsizei depth, GLenum format, GLenum type, GLint level, GLint base,
                                        GLint max, const void* data) {
  if (const GLint rc = checkMipmapArgs(format, type)) return rc;
  if (width < 1 || height < 1 || depth < 1) return GLU_INVALID_VALUE;
  const int levels = std::max({log2Exact(width), log2Exact(height), log2Exact(depth)}) + level;
  if (!legalLevels(level, base, max, levels)) return GLU_INVALID_VALUE;
  return build3DCore(target, internalFormat, width, height, depth, width, height, depth, format, type, level,
                     base, max, data);
}

GLint GLAPIENTRY gluBuild3DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                   GLsizei depth, GLenum format, GLenum type, const void* data) {
  if (const GLint rc = checkMipmapArgs(format, type)) return rc;
  if (width < 1 || height < 1 || depth < 1) return GLU_INVALID_VALUE;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  if (maxSize < 1) maxSize = 16;  // GL 1.2 guarantees at least 16
  const int newWidth = std::min(nearestPower(width), int(maxSize));
  const int newHeight = std::min(nearestPower(height), int(maxSize));
  const int newDepth = std::min(nearestPower(depth), int(maxSize));
  const int levels = std::max({floorLog2(newWidth), floorLog2(newHeight), floorLog2(newDepth)});
  return build3DCore(target, internalFormat, width, height, depth, newWidth, newHeight, newDepth, format,
                     type, 0, 0, levels, data);
}

}  // extern "C"
