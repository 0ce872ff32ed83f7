// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerClampedSetter.h
 * @brief BP_CLAMPED_SETTER: vtkBoundParticleTracer's setters that keep a value
 * in its range, for the enumerated properties (generated) and the numeric ones.
 */
#ifndef BoundParticles_TracerClampedSetter_h
#define BoundParticles_TracerClampedSetter_h

// vtkSetClampMacro, but a value out of range (from a script or a saved state
// file) is said, not silently changed. NaN takes the minimum.
#define BP_CLAMPED_SETTER(name, type, low, high)                                                   \
  void vtkBoundParticleTracer::Set##name(type value)                                               \
  {                                                                                                \
    const type lowest = static_cast<type>(low), highest = static_cast<type>(high);                 \
    const type clamped = !(value >= lowest) ? lowest : (value > highest ? highest : value);        \
    if (!(clamped == value))                                                                       \
    {                                                                                              \
      vtkWarningMacro(<< #name " " << value << " is outside [" << lowest << ", " << highest        \
                      << "]; using " << clamped << ".");                                           \
    }                                                                                              \
    if (this->name != clamped)                                                                     \
    {                                                                                              \
      this->name = clamped;                                                                        \
      this->Modified();                                                                            \
    }                                                                                              \
  }

#endif
