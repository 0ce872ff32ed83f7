// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pqBoundParticleIsTracer.h
 * @brief Whether a proxy is a Bound Particle Tracer: the one test the GUI
 * helpers (defaults, Play updates, the trails display) pick tracers by.
 */
#ifndef pqBoundParticleIsTracer_h
#define pqBoundParticleIsTracer_h

#include "vtkSMProxy.h"

#include <cstring>

/// True for the proxy of a Bound Particle Tracer (false for null).
inline bool pqBoundParticleIsTracer(vtkSMProxy* proxy)
{
  return proxy && proxy->GetXMLName() && !std::strcmp(proxy->GetXMLName(), "BoundParticleTracer");
}

#endif
