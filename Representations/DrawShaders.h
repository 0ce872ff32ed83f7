// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DrawShaders.h
 * @brief Splices the display's drawing code (Shaders/bp_draw_*.glsl) into
 * VTK's polydata shaders.
 *
 * vtkOpenGLBoundParticleMapper draws with VTK's own shaders, so lighting and
 * the rest of the Surface representation's look apply unchanged; only where
 * a vertex's position, normal and colour scalar come from differs. The
 * splice runs in two halves around VTK's own replacements: tags of the
 * display's own first, placed after VTK's tags so that the code they become
 * runs after VTK's, then the code itself.
 */
#ifndef BoundParticles_DrawShaders_h
#define BoundParticles_DrawShaders_h

#include "vtkShader.h" // for vtkShader::Type

#include <map>

namespace bpvtk
{

using ShaderMap = std::map<vtkShader::Type, vtkShader*>;

/// Before VTK's replacements: the //BP:: tags after VTK's colour code (the
/// geometry and fragment shaders) and after its view-coordinate position.
void addDrawTags(ShaderMap& shaders);

/**
 * After VTK's replacements: every use of the vertex and normal attributes
 * reads the values fetched from the engine's textures (the attributes stay
 * declared, so VTK's buffers still bind), the fetch and the clipping of
 * hidden elements go into the vertex shader, the colour scalar is passed on
 * through a geometry shader where VTK uses one (wide lines), and the
 * fragment shader colours by the lookup table texture. The colour modes'
 * numbers come from the table of output arrays (bp::colorSourceDefinitions).
 */
void spliceDrawCode(ShaderMap& shaders);

} // namespace bpvtk

#endif
