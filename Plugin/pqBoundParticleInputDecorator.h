// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class pqBoundParticleInputDecorator
 * @brief Shows or enables a tracer property by what its inputs are.
 *
 * XML: `<PropertyWidgetDecorator type="BoundParticleInputDecorator"
 * input="Input" when="steady" mode="visibility"/>`, where `input` names an
 * input property of the proxy and `when` is one of
 *  - `steady` / `unsteady`: that input has fewer than two / at least two time steps;
 *  - `connected` / `unconnected`: that input is connected / not;
 *  - `resampled`: that input is traced through a resampled grid (a mesh, a
 *    composite: anything but an image or a rectilinear grid);
 *  - `emitter_box`: elements are released in the emitter box: that input
 *    (the Seed Source) is not connected, and the proxy property named by
 *    `seed_type` (default `SeedType`) holds the Emitter Box entry of its list.
 * `mode` is `visibility` (hide the widget otherwise) or `enabled_state`
 * (grey it out otherwise). So Duration shows only for a steady field,
 * Element Shape greys out once an Element Template is connected, and the
 * emitter box widget shows only while the box is where releases happen.
 */
#ifndef pqBoundParticleInputDecorator_h
#define pqBoundParticleInputDecorator_h

#include "pqPropertyWidgetDecorator.h"

#include "vtkWeakPointer.h"

#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkSMProperty;

class pqBoundParticleInputDecorator : public pqPropertyWidgetDecorator
{
  typedef pqPropertyWidgetDecorator Superclass;

public:
  pqBoundParticleInputDecorator(vtkPVXMLElement* config, pqPropertyWidget* parent);
  ~pqBoundParticleInputDecorator() override;

  bool canShowWidget(bool showAdvanced) const override;
  bool enableWidget() const override;

private:
  /// Whether the input meets the `when` condition.
  bool conditionHolds() const;
  /// Whether this decorator acts in `mode`.
  bool actsAs(const char* mode) const;
  /// Tells the panel to look again (the input or its data changed).
  void inputChanged();

  /// Watches `property` for changes the panel makes before Apply.
  void observe(vtkSMProperty* property);

  vtkWeakPointer<vtkSMProperty> Input;
  vtkWeakPointer<vtkSMProperty> SeedType; ///< for `emitter_box`
  /// (property, observer) pairs to remove.
  std::vector<std::pair<vtkWeakPointer<vtkSMProperty>, unsigned long>> Observers;

  Q_DISABLE_COPY(pqBoundParticleInputDecorator)
};

#endif
