// SPDX-License-Identifier: BSD-3-Clause
// The display's drawing code spliced into VTK's polydata shaders (DrawShaders.h).
#include "DrawShaders.h"

#include "BoundParticlesShaders.h" // generated from Shaders/
#include "OutputArrays.h"
#include "ShaderSource.h"

#include "vtkShaderProgram.h"

#include <string>

namespace bpvtk
{

void addDrawTags(ShaderMap& shaders)
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(fs, "//VTK::Color::Impl", "//VTK::Color::Impl\n//BP::Color::Impl");
  vtkShaderProgram::Substitute(fs, "//VTK::Color::Dec", "//VTK::Color::Dec\n//BP::Color::Dec");
  vtkShaderProgram::Substitute(
    vs, "//VTK::PositionVC::Impl", "//VTK::PositionVC::Impl\n//BP::PositionVC::Impl");
  // With a geometry shader (wide lines where the GL has none of its own) the
  // fragment shader's inputs are renamed to come from it (VSOutput becomes
  // GSOutput): it must pass the scalar on, as VTK's colour code does.
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  vtkShaderProgram::Substitute(gs, "//VTK::Color::Impl", "//VTK::Color::Impl\n//BP::Color::Impl");
  vtkShaderProgram::Substitute(gs, "//VTK::Color::Dec", "//VTK::Color::Dec\n//BP::Color::Dec");
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Geometry]->SetSource(gs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

void spliceDrawCode(ShaderMap& shaders)
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(
    gs, "//BP::Color::Dec", "in float bpScalarVSOutput[];\nout float bpScalarGSOutput;", false);
  vtkShaderProgram::Substitute(
    gs, "//BP::Color::Impl", "bpScalarGSOutput = bpScalarVSOutput[i];", false);
  shaders[vtkShader::Geometry]->SetSource(gs);
  // The colour sources and the engine's constants (bp_shared.glsl's hash
  // and draws) as #defines, ahead of the draw's declarations.
  const std::string colorModes = bp::colorSourceDefinitions() + bp::engineConstantDefinitions();
  vtkShaderProgram::Substitute(vs, "vertexMC", "bpVertexMC", true);
  vtkShaderProgram::Substitute(vs, "normalMC", "bpNormalMC", true);
  vtkShaderProgram::Substitute(
    vs, "in vec4 bpVertexMC;", "in vec4 vertexMC;\n" + colorModes + bpShaderDrawVSDec, false);
  vtkShaderProgram::Substitute(vs, "in vec3 bpNormalMC;", "in vec3 normalMC;", false);
  vtkShaderProgram::Substitute(
    vs, "void main()\n{", std::string("void main()\n{\n") + bpShaderDrawVSImpl, false);
  vtkShaderProgram::Substitute(vs, "//BP::PositionVC::Impl", "  bpClipHidden();", false);
  vtkShaderProgram::Substitute(fs, "//BP::Color::Dec", colorModes + bpShaderDrawFSDec, false);
  vtkShaderProgram::Substitute(fs, "//BP::Color::Impl", bpShaderDrawFSImpl, false);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

} // namespace bpvtk
