// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TrailFade.h
 * @brief The trails' fade for the Bound Particles display's CPU path.
 *
 * The GPU mapper fades each trail pose by 1 - age / span, span one trail
 * interval past the oldest pose, unless the colour map maps opacity itself.
 * A polydata mapper cannot scale a mapped colour's alpha per point, so the
 * display's CPU path maps the colours here, scales their alpha, and draws
 * them as direct scalars: the same look on both engines.
 */
#ifndef BoundParticles_TrailFade_h
#define BoundParticles_TrailFade_h

#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkPolyData;
class vtkScalarsToColors;
class vtkUnsignedCharArray;

namespace bpvtk
{

/// The span over which `piece`'s trail poses fade (its "TrailFadeSpan"
/// field value); 0 when it has no trail poses to fade.
double trailFadeSpan(vtkPolyData* piece);

/// What a faded colouring draws: the colour array (empty: the solid colour)
/// and its component (-1: the magnitude) through `lut`.
struct TrailColoring
{
  const char* array = nullptr;
  int component = -1;
  vtkScalarsToColors* lut = nullptr;
  double solid[3] = { 1, 1, 1 };
};

/// Per point of `piece`: the RGBA colour the coloring gives, its alpha
/// scaled by 1 - Age / span (clamped to [0, 1]); null without Age.
vtkSmartPointer<vtkUnsignedCharArray> fadedTrailColors(
  vtkPolyData* piece, const TrailColoring& coloring, double span);

} // namespace bpvtk

#endif
