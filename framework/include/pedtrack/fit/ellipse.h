#pragma once
// Direct least-squares ellipse fit (Fitzgibbon, Pilu & Fisher 1999; P4 ref. 36).
#include "pedtrack/fit/circle.h"

namespace pedtrack::fit {

struct Ellipse {
  double x = 0, y = 0;  ///< centre
  double a = 0, b = 0;  ///< semi-axes, a ≥ b
  double angle = 0;     ///< direction of the `a` axis (rad, in (−π/2, π/2])
};

/// Fitzgibbon's direct fit (the ellipse-specific conic minimising the algebraic distance), in
/// Halíř & Flusser's stable form. False for fewer than 5 points or a degenerate conic.
bool fitEllipseDirect(const Points2& pts, Ellipse& out);

/// Root mean square of each point's radial distance to the ellipse (along the ray from the
/// centre: |1 − 1/k|·|p − c| with k² = u²/a² + v²/b² in the ellipse's axes), m.
double ellipseResidual(const Points2& pts, const Ellipse& e);

}  // namespace pedtrack::fit
