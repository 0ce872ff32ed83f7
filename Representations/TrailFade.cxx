// SPDX-License-Identifier: BSD-3-Clause
#include "TrailFade.h"

#include "OutputArrays.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

namespace bpvtk
{

namespace
{
vtkDataArray* ageOf(vtkPolyData* piece)
{
  return piece ? piece->GetPointData()->GetArray(bp::outputArray(bp::OutputArrayId::Age).name)
               : nullptr;
}
} // namespace

void chooseTrailPoses(const std::vector<bp::GpuEngine::DrawInputs::TrailSlot>& slots, double time,
  double fadeSpan, bool mapFades, std::vector<TrailPoseDraw>& poses)
{
  poses.clear();
  for (const auto& slot : slots)
  {
    if (slot.time < time && slot.positions && slot.elements)
    {
      const double age = time - slot.time;
      const double fade = mapFades || !(fadeSpan > 0.0) ? 1.0 : trailFade(age, fadeSpan);
      poses.push_back({ slot.positions, slot.elements, float(age), float(fade) });
    }
  }
}

double trailFadeSpan(vtkPolyData* piece)
{
  vtkDataArray* age = ageOf(piece);
  vtkDataArray* span = piece ? piece->GetFieldData()->GetArray("TrailFadeSpan") : nullptr;
  if (!age || !span || span->GetNumberOfTuples() < 1 || age->GetNumberOfTuples() < 1)
  {
    return 0.0;
  }
  // Without a pose older than the elements themselves nothing fades.
  const double value = span->GetTuple1(0);
  return age->GetRange(0)[1] > 0.0 && std::isfinite(value) && value > 0.0 ? value : 0.0;
}

vtkSmartPointer<vtkUnsignedCharArray> fadedTrailColors(
  vtkPolyData* piece, const TrailColoring& coloring, double span)
{
  vtkDataArray* age = ageOf(piece);
  if (!age)
  {
    return nullptr;
  }
  const vtkIdType n = piece->GetNumberOfPoints();
  vtkDataArray* values = coloring.array && coloring.array[0] && coloring.lut
    ? piece->GetPointData()->GetArray(coloring.array)
    : nullptr;
  vtkSmartPointer<vtkUnsignedCharArray> colors;
  if (values)
  {
    // The colour map's own colours, as the mapper would map them.
    colors.TakeReference(
      coloring.lut->MapScalars(values, VTK_COLOR_MODE_MAP_SCALARS, coloring.component, 4));
  }
  else
  {
    colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetNumberOfComponents(4);
    colors->SetNumberOfTuples(n);
    unsigned char rgba[4] = { 255, 255, 255, 255 };
    for (int c = 0; c < 3; ++c)
    {
      rgba[c] = static_cast<unsigned char>(
        std::lround(255.0 * std::min(std::max(coloring.solid[c], 0.0), 1.0)));
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      colors->SetTypedTuple(i, rgba);
    }
  }
  if (!colors || colors->GetNumberOfTuples() != n || colors->GetNumberOfComponents() != 4)
  {
    return nullptr;
  }
  colors->SetName("BoundParticlesFadedColors");
  unsigned char* rgba = colors->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double fade = trailFade(age->GetComponent(i, 0), span);
    rgba[4 * i + 3] = static_cast<unsigned char>(std::lround(rgba[4 * i + 3] * fade));
  }
  return colors;
}

} // namespace bpvtk
