#include "server/core/tiling/cells/circumdisk.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace locator {

namespace {

// 2^k, for the k that are normal exponents (else 0: see Scale).
double PowerOfTwo(int k) {
  return k > -1022 && k < 1024
             ? std::bit_cast<double>(static_cast<uint64_t>(1023 + k) << 52)
             : 0;
}

// v * 2^k, exactly as std::ldexp but for a multiplication when 2^k is a
// normal double (`power`, from PowerOfTwo).
double Scale(double v, double power, int k) {
  return power != 0 ? v * power : std::ldexp(v, k);
}

}  // namespace

// The error analysis, with u = 2^-53 the unit roundoff. With B = b - a and
// C = c - a, the centre is a + (Nx, Ny) / D, where
//   Nx = Cy |B|^2 - By |C|^2,  Ny = Bx |C|^2 - Cx |B|^2,
//   D = 2 (Bx Cy - By Cx).
// Rounding B and C perturbs each coordinate by a relative 1.01u, so each
// cubic monomial of N by at most 3.04u and each product of D by 2.03u;
// evaluating N then adds at most gamma_4 = 4.01u of the sum M_N of its
// monomials' magnitudes, and D gamma_2 of M_D. So the computed n and d are
// within 7.05u M_N and 4.04u M_D of the exact values for a, b, c; below, 9u
// and 5u (with M_N and M_D themselves computed) cover them. Scaling B and C
// by a power of two first keeps every product in range; subnormal results
// add at most a few 2^-1074, covered by kTiny. Then
//   |N/D - n/d| <= (e_N |d| + |n| e_D) / (|d| (|d| - e_D)),
// doubled for its own rounding, plus u |n/d| for the division.
bool CircumdiskBound(const Point2& a, const Point2& b, const Point2& c,
                     Disk* out) {
  constexpr double u = 0x1p-53;
  constexpr double kTiny = 1e-300;
  double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double largest =
      std::max({std::abs(bx), std::abs(by), std::abs(cx), std::abs(cy)});
  if (!(largest > 0) || !std::isfinite(largest)) return false;
  int exponent = 0;
  std::frexp(largest, &exponent);
  const double down = PowerOfTwo(-exponent);
  bx = Scale(bx, down, -exponent);
  by = Scale(by, down, -exponent);
  cx = Scale(cx, down, -exponent);
  cy = Scale(cy, down, -exponent);

  const double sb = bx * bx + by * by;
  const double sc = cx * cx + cy * cy;
  const double nx = cy * sb - by * sc;
  const double ny = bx * sc - cx * sb;
  const double d = 2 * (bx * cy - by * cx);
  const double en_x = 9 * u * (std::abs(cy) * sb + std::abs(by) * sc) + kTiny;
  const double en_y = 9 * u * (std::abs(bx) * sc + std::abs(cx) * sb) + kTiny;
  const double ed = 10 * u * (std::abs(bx * cy) + std::abs(by * cx)) + kTiny;
  const double ad = std::abs(d);
  if (!(ad > 2 * ed)) return false;
  const double ux = nx / d;
  const double uy = ny / d;
  const double denominator = ad * (ad - ed);
  const double ex =
      2 * ((en_x * ad + std::abs(nx) * ed) / denominator + u * std::abs(ux));
  const double ey =
      2 * ((en_y * ad + std::abs(ny) * ed) / denominator + u * std::abs(uy));
  const double offset = std::sqrt(ux * ux + uy * uy);

  // Back to the input's scale: exact but for overflow (caught below) and
  // subnormals (a few 2^-1074, covered by the smallest normal double: a
  // subnormal operand would cost a microcode assist on every call).
  const double tiny = std::numeric_limits<double>::min();
  const double up = PowerOfTwo(exponent);
  const Point2 center{a.x + Scale(ux, up, exponent),
                      a.y + Scale(uy, up, exponent)};
  // The computed centre is within this of the true one (the addition of a
  // rounds by u of the centre's magnitude).
  const double rounding = 1.01 * u * (std::abs(center.x) + std::abs(center.y));
  const double center_error =
      Scale(ex, up, exponent) + Scale(ey, up, exponent) + rounding + tiny;
  // The true circle lies within |centre - a| + 2 * center_error of the
  // computed centre; |centre - a| is the offset plus the addition's rounding.
  const double radius =
      (Scale(offset, up, exponent) + rounding + 2 * center_error + tiny) *
      (1 + 1e-14);
  if (!std::isfinite(center.x) || !std::isfinite(center.y) ||
      !std::isfinite(radius)) {
    return false;
  }
  out->center = center;
  out->radius = radius;
  return true;
}

}  // namespace locator
