// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TrailFade.h
 * @brief The trails' fade for the Bound Particles display, on both paths.
 *
 * Both paths fade each trail pose by 1 - age / span (trailFade), span one
 * trail interval past the oldest pose, unless the colour map maps opacity
 * itself. The GPU mapper draws each pose shown (chooseTrailPoses) with its
 * fade as a uniform of its draw shader. A polydata mapper cannot scale a
 * mapped colour's alpha per point, so the display's CPU path maps the
 * colours here, scales their alpha, and draws them as direct scalars: the
 * same look on both engines.
 */
#ifndef BoundParticles_TrailFade_h
#define BoundParticles_TrailFade_h

#include "GpuEngine.h"       // for bp::GpuEngine::DrawInputs::TrailSlot
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <algorithm> // for std::min, std::max
#include <vector>    // for std::vector

class vtkPolyData;
class vtkScalarsToColors;
class vtkUnsignedCharArray;

namespace bpvtk
{

/// The opacity factor of a trail pose `age` old whose trail fades over
/// `span`: 1 - age / span, clamped to [0, 1]. Inline: the CPU path applies
/// it to every point.
inline double trailFade(double age, double span)
{
  return std::min(std::max(1.0 - age / span, 0.0), 1.0);
}

/// A trail pose the GPU mapper draws: the slot's particle and element
/// textures, its age and its fade. (Not TrailPose: the tracer's output has a
/// bpvtk::TrailPose of its own in the same plugin library.)
struct TrailPoseDraw
{
  unsigned positions, elements;
  float age, fade;
};

/**
 * The trail poses to draw at `time`, newest first, into `poses`: the slots
 * recorded strictly before it (a step shown and taken back leaves none ahead
 * of it), as the CPU output's trailPoses(). Each fades by trailFade over
 * `fadeSpan` (the trail's span plus one interval: the newest pose, one
 * interval old, at L / (L + 1), the oldest at 1 / (L + 1)), or not at all
 * where `mapFades` (the colour map maps opacity) or the span is not positive.
 */
void chooseTrailPoses(const std::vector<bp::GpuEngine::DrawInputs::TrailSlot>& slots, double time,
  double fadeSpan, bool mapFades, std::vector<TrailPoseDraw>& poses);

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
