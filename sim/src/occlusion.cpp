#include "touchline/sim/occlusion.hpp"

namespace touchline::sim {

bool body_hides(const Pose2D& eye, const Pose2D& body, float radius_mm, float x_mm, float y_mm) {
  if (!(radius_mm > 0)) return false;
  // Double precision: squared field distances (~1e7 mm^2) would lose the sub-millimetre
  // part in float.
  const double tx = double(x_mm) - eye.x_mm, ty = double(y_mm) - eye.y_mm;   // eye -> target
  const double bx = double(body.x_mm) - eye.x_mm, by = double(body.y_mm) - eye.y_mm; // eye -> body
  const double target2 = tx * tx + ty * ty, body2 = bx * bx + by * by;
  const double r2 = double(radius_mm) * radius_mm;
  if (body2 <= r2 || body2 >= target2) return false; // eye inside the disc, or body not nearer
  const double along = bx * tx + by * ty;            // |t| * (body's projection on the sight line)
  if (along <= 0) return false;                      // the body is beside or behind the eye
  // Squared distance from the body centre to the sight line; since the body is nearer
  // than the target and in front, its foot point lies on the segment eye -> target.
  const double off2 = body2 - along * along / target2;
  return off2 < r2;
}

} // namespace touchline::sim
