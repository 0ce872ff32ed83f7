// Drawing (vtkOpenGLBoundParticleMapper): declarations added to VTK's polydata
// vertex shader. The element draw is one instance per element, one vertex per
// template particle; the link draw of a super set is one instance per link,
// vertices 2i and 2i + 1 being particle i of its two elements. Either way the
// position and normal come from the GPU engine's state textures (vertex
// texture fetch), never from a buffer uploaded per frame.
uniform sampler2D bpPositions; // per particle: grid-local position, force
uniform sampler2D bpNormals;   // per particle: unit normal
uniform sampler2D bpSamples;   // per particle: velocity, |curl v|
uniform sampler2D bpElements;  // per element: lifetime, generation, flags
uniform sampler2D bpCenters;   // per element: the generation's initial centre, hidden
uniform isampler2D bpLinks;    // per link: its two elements (the CPU output's link cells)
uniform int bpLinksPerRow;
uniform int bpDrawLinks;       // 1 in the link draw, 0 in the element draw
uniform ivec2 bpElementGrid;
uniform int bpBlocksPerRow;
uniform vec3 bpOffset;         // world position of the grid-local origin
uniform int bpScalarMode;      // a BP_COLOR_* of Core/OutputArrays.h (ColorSource)
uniform int bpComponent;       // for Velocity: 0-2, or -1 for the magnitude
uniform vec2 bpScalarRange;    // the lookup table's range
uniform int bpColoringAxis;
uniform vec2 bpRadialCenter;   // grid-local, on the two other axes
out float bpScalarVSOutput;    // the scalar, scaled to [0, 1] over the range
vec4 bpVertexMC;
vec3 bpNormalMC;
bool bpHidden; // the element, or an element of the link, was placed outside the release window

ivec2 bpDrawTexel(int e, int i)
{
  ivec2 block = ivec2(i % bpBlocksPerRow, i / bpBlocksPerRow);
  return block * bpElementGrid + ivec2(e % bpElementGrid.x, e / bpElementGrid.x);
}

bool bpHiddenElement(int e)
{
  return texelFetch(bpCenters, ivec2(e % bpElementGrid.x, e / bpElementGrid.x), 0).w > 0.5;
}

// A hidden element is not drawn: every vertex of its primitives lies outside
// the clip volume, so none is rasterized. Discarding its fragments instead
// would come too late under depth peeling, whose fragment code returns early
// after writing the fragment's depth into the peels.
void bpClipHidden()
{
  if (bpHidden)
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  }
}

float bpScalarOf(int e, int i, ivec2 texel, vec4 state)
{
  ivec2 elementTexel = ivec2(e % bpElementGrid.x, e / bpElementGrid.x);
  if (bpScalarMode == BP_COLOR_FORCE)
    return state.w;
  if (bpScalarMode == BP_COLOR_LIFETIME)
    return max(texelFetch(bpElements, elementTexel, 0).x, 0.0); // none left, as the CPU output
  if (bpScalarMode == BP_COLOR_VELOCITY)
  {
    vec3 v = texelFetch(bpSamples, texel, 0).xyz;
    return bpComponent >= 0 ? v[bpComponent] : length(v);
  }
  if (bpScalarMode == BP_COLOR_VORTICITY)
    return texelFetch(bpSamples, texel, 0).w;
  vec3 c = texelFetch(bpCenters, elementTexel, 0).xyz;
  if (bpScalarMode == BP_COLOR_LAYER)
    return c[bpColoringAxis] + bpOffset[bpColoringAxis];
  if (bpScalarMode == BP_COLOR_RADIUS)
  {
    vec2 d = vec2(c[(bpColoringAxis + 1) % 3], c[(bpColoringAxis + 2) % 3]) - bpRadialCenter;
    return length(d);
  }
  if (bpScalarMode == BP_COLOR_ELEMENT_INDEX)
    return float(e);
  if (bpScalarMode == BP_COLOR_PARTICLE_INDEX)
    return float(i);
  return 0.0;
}
