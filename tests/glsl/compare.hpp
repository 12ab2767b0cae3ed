// Value-for-value comparison of Tessel's and Mesa's float outputs, with a stated tolerance.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace tessel::testing {

struct Tolerance {
  float abs = 0.0f;  // |a - b| <= abs + rel * |b| passes
  float rel = 0.0f;
};

struct Mismatch {
  int count = 0;
  std::string first;  // where and what, for the first few
};

// NaN matches NaN, infinities match themselves; channels with mask bit clear are skipped.
inline Mismatch compare_floats(const std::vector<float>& a, const std::vector<float>& b, int width,
                               Tolerance tol, unsigned channel_mask = 0xF) {
  Mismatch m;
  std::ostringstream os;
  os.precision(9);
  if (a.size() != b.size()) {
    m.count = 1;
    m.first = "sizes differ";
    return m;
  }
  for (size_t i = 0; i < a.size(); ++i) {
    if (!((channel_mask >> (i % 4)) & 1)) continue;
    const float x = a[i], y = b[i];
    bool same;
    if (std::isnan(y))
      same = std::isnan(x);
    else if (std::isinf(y))
      same = x == y;
    else
      same = std::isfinite(x) && std::fabs(x - y) <= tol.abs + tol.rel * std::fabs(y);
    if (!same) {
      if (m.count < 4) {
        const size_t p = i / 4;
        os << " pixel (" << p % size_t(width) << "," << p / size_t(width) << ")."
           << "rgba"[i % 4] << ": tessel " << x << " mesa " << y << ";";
      }
      ++m.count;
    }
  }
  m.first = os.str();
  return m;
}

}  // namespace tessel::testing
