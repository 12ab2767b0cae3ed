// The GL type enum (glGetActiveUniform, glGetActiveAttrib) of a glslang type.
#pragma once

#include <glslang/Include/Types.h>

#include <cstdint>

namespace tessel::glsl {

// GL 3.3 Table 2.10 (uniform types); 0 for a type GL has no enum for (structs).
inline uint32_t gl_type_of(const glslang::TType& t) {
  using namespace glslang;
  if (t.isMatrix()) {
    static constexpr uint32_t m[3][3] = {{0x8B5A, 0x8B65, 0x8B66},   // mat2, mat2x3, mat2x4
                                         {0x8B67, 0x8B5B, 0x8B68},   // mat3x2, mat3, mat3x4
                                         {0x8B69, 0x8B6A, 0x8B5C}};  // mat4x2, mat4x3, mat4
    const int c = t.getMatrixCols(), r = t.getMatrixRows();
    if (c < 2 || c > 4 || r < 2 || r > 4) return 0;
    return m[c - 2][r - 2];
  }
  const int n = t.getVectorSize() > 0 ? t.getVectorSize() : 1;
  switch (t.getBasicType()) {
    case EbtFloat: return n == 1 ? 0x1406 : 0x8B50 + uint32_t(n - 2);  // FLOAT, FLOAT_VEC2..4
    case EbtInt: return n == 1 ? 0x1404 : 0x8B53 + uint32_t(n - 2);    // INT, INT_VEC2..4
    case EbtUint: return n == 1 ? 0x1405 : 0x8DC6 + uint32_t(n - 2);   // UNSIGNED_INT, ..._VEC2..4
    case EbtBool: return n == 1 ? 0x8B56 : 0x8B57 + uint32_t(n - 2);   // BOOL, BOOL_VEC2..4
    case EbtSampler: {
      const TSampler& s = t.getSampler();
      const int kind = s.type == EbtInt ? 1 : s.type == EbtUint ? 2 : 0;
      switch (s.dim) {
        case Esd1D:
          if (s.isShadow()) return s.isArrayed() ? 0x8DC3 : 0x8B61;
          if (s.isArrayed()) return kind == 0 ? 0x8DC0 : kind == 1 ? 0x8DCE : 0x8DD6;
          return kind == 0 ? 0x8B5D : kind == 1 ? 0x8DC9 : 0x8DD1;
        case Esd2D:
          // GL_SAMPLER_2D_MULTISAMPLE(_ARRAY) and their int and unsigned forms.
          if (s.isMultiSample()) return (s.isArrayed() ? 0x910B : 0x9108) + uint32_t(kind);
          if (s.isShadow()) return s.isArrayed() ? 0x8DC4 : 0x8B62;
          if (s.isArrayed()) return kind == 0 ? 0x8DC1 : kind == 1 ? 0x8DCF : 0x8DD7;
          return kind == 0 ? 0x8B5E : kind == 1 ? 0x8DCA : 0x8DD2;
        case Esd3D: return kind == 0 ? 0x8B5F : kind == 1 ? 0x8DCB : 0x8DD3;
        case EsdCube:
          if (s.isShadow()) return 0x8DC5;
          return kind == 0 ? 0x8B60 : kind == 1 ? 0x8DCC : 0x8DD4;
        case EsdRect:
          if (s.isShadow()) return 0x8B64;
          return kind == 0 ? 0x8B63 : kind == 1 ? 0x8DCD : 0x8DD5;
        case EsdBuffer: return kind == 0 ? 0x8DC2 : kind == 1 ? 0x8DD0 : 0x8DD8;
        default: return 0;
      }
    }
    default: return 0;
  }
}

}  // namespace tessel::glsl
