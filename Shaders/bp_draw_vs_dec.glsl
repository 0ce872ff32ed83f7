// Drawing (vtkOpenGLBoundParticleMapper): declarations added to VTK's polydata
// vertex shader. The element draw is one instance per element, one vertex per
// template particle; the link draw of a super set is one instance per link,
// vertices 2i and 2i + 1 being particle i of its two elements. Either way the
// position and normal come from the GPU engine's state textures (vertex
// texture fetch), never from a buffer uploaded per frame. A motion trail's
// pose is the element draw again (bpTrail 1) with the positions of one slot
// of the engine's trail ring and normals computed here from them.
// Gpu/CMakeLists.txt puts bp_shared.glsl (the texture layout, the normals'
// arithmetic) before this file in the embedded bpShaderDrawVSDec.
//
// Model coordinates are the engine's grid-local ones, as fetched: the mapper
// composes the translation to world coordinates into MCDCMatrix and
// MCVCMatrix in double (vtkOpenGLBoundParticleMapper::SetCameraShaderParameters).
// Adding the offset here, in float, would round a field 6.4e6 from the
// origin to 0.5 and one 1e8 away to 8.
uniform sampler2D bpPositions; // per particle: grid-local position, force
uniform sampler2D bpNormals;   // per particle: unit normal
uniform sampler2D bpSamples;   // per particle: velocity, |curl v|
uniform sampler2D bpElements;  // per element: lifetime, generation, flags
uniform sampler2D bpCenters;   // per element: the generation's initial centre, hidden
uniform isampler2D bpLinks;    // per link: its two elements (the CPU output's link cells)
uniform sampler2D bpPoses;     // per element: pose quaternion (x, y, z, w)
uniform sampler2D bpSpins;     // per element: angular velocity xyz, SpinVorticityRatio
uniform sampler2D bpTrailPositions; // per particle, in the trail draw: the slot's positions
uniform sampler2D bpTrailElements;  // per element, in the trail draw: the slot's generation (.y)
uniform isampler2D bpAdjacency; // per template particle (row): the triangles it is a corner of
uniform int bpAdjacencyWidth;  // texels a row; a row ends early at a corner index of -1
uniform int bpTrail;           // 1 in a trail pose's draw, 0 otherwise
uniform float bpTrailAge;      // in a trail pose's draw: the shown time minus the slot's
uniform int bpLinksPerRow;
uniform int bpDrawLinks;       // 1 in the link draw, 0 in the element draw
uniform int bpScalarMode;      // a BP_COLOR_* of Core/OutputArrays.h (ColorSource)
uniform int bpComponent;       // for vector sources: a component, or -1 for the magnitude
uniform vec2 bpScalarRange;    // the lookup table's range (Layer's: grid-local)
uniform int bpColoringAxis;
uniform vec2 bpRadialCenter;   // grid-local, on the two other axes
out float bpScalarVSOutput;    // the scalar, scaled to [0, 1] over the range
vec4 bpVertexMC;
vec3 bpNormalMC;
bool bpHidden; // the element, or an element of the link, was placed outside the release window

bool bpHiddenElement(int e)
{
  return texelFetch(bpCenters, bpElementTexel(e), 0).w > 0.5;
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
  ivec2 elementTexel = bpElementTexel(e);
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
    return c[bpColoringAxis]; // grid-local, as bpScalarRange is for Layer
  if (bpScalarMode == BP_COLOR_RADIUS)
  {
    vec2 d = vec2(c[(bpColoringAxis + 1) % 3], c[(bpColoringAxis + 2) % 3]) - bpRadialCenter;
    return length(d);
  }
  if (bpScalarMode == BP_COLOR_ELEMENT_INDEX)
    return float(e);
  if (bpScalarMode == BP_COLOR_PARTICLE_INDEX)
    return float(i);
  if (bpScalarMode == BP_COLOR_ORIENTATION)
  {
    vec4 q = texelFetch(bpPoses, elementTexel, 0);
    return bpComponent >= 0 ? q[bpComponent] : length(q);
  }
  if (bpScalarMode == BP_COLOR_SPIN)
  {
    vec3 w = texelFetch(bpSpins, elementTexel, 0).xyz;
    return bpComponent >= 0 ? w[bpComponent] : length(w);
  }
  if (bpScalarMode == BP_COLOR_SPIN_RATIO)
    return texelFetch(bpSpins, elementTexel, 0).w;
  if (bpScalarMode == BP_COLOR_AGE)
    return bpTrail != 0 ? bpTrailAge : 0.0;
  return 0.0;
}

// Whether element e has no pose in the trail slot drawn: the slot holds
// another generation's (a released element starts a new trail), or none.
bool bpNotInTrail(int e)
{
  ivec2 elementTexel = bpElementTexel(e);
  return texelFetch(bpTrailElements, elementTexel, 0).y != texelFetch(bpElements, elementTexel, 0).y;
}

// Particle i's normal in element e's trail pose, as the CPU output computes a
// pose's normals (bp::elementNormals, bp_shared.glsl).
vec3 bpTrailNormal(int e, int i)
{
  vec3 sum = vec3(0.0);
  for (int k = 0; k < bpAdjacencyWidth; ++k)
  {
    ivec4 corners = texelFetch(bpAdjacency, ivec2(k, i), 0);
    if (corners.x < 0)
      break;
    vec3 a = texelFetch(bpTrailPositions, bpParticleTexel(e, corners.x), 0).xyz;
    vec3 b = texelFetch(bpTrailPositions, bpParticleTexel(e, corners.y), 0).xyz;
    vec3 c = texelFetch(bpTrailPositions, bpParticleTexel(e, corners.z), 0).xyz;
    bpAddTriangleNormal(sum, a, b, c);
  }
  return bpNormalOfSum(sum);
}
