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
uniform sampler2D bpSlips;     // per particle: heavy particles' slip (none bound: 0)
uniform sampler2D bpTrailPositions; // per particle, in the trail draw: the slot's positions
uniform sampler2D bpTrailElements;  // per element, in the trail draw: the slot's generation (.y)
uniform isampler2D bpAdjacency; // per template particle (row): the triangles it is a corner of
uniform int bpAdjacencyWidth;  // texels a row; a row ends early at a corner index of -1
uniform int bpTrail;           // 1 in a trail pose's draw, 0 otherwise
uniform float bpTrailAge;      // in a trail pose's draw: the shown time minus the slot's
uniform vec3 bpTrailHalfPeriods; // half of each periodic axis's period, 0 along the others
uniform int bpLinksPerRow;
uniform int bpDrawLinks;       // 1 in the link draw, 0 in the element draw
uniform int bpScalarMode;      // a BP_COLOR_* of Core/Output/OutputArrays.h (ColorSource)
uniform int bpComponent;       // for vector sources: a component, or -1 for the magnitude
uniform vec2 bpScalarRange;    // the lookup table's range (Layer's: grid-local)
uniform int bpColoringAxis;
uniform vec2 bpRadialCenter;   // grid-local, on the two other axes
uniform float bpVelocitySign;  // -1 backward: Velocity and ElementSpin per the data's time
// ElementStretch and ElementFTLE (bp::StretchFit, Core/Elements/ElementStretch.h):
uniform sampler2D bpStretchRest; // template particle i at (i % width, i / width): rest - mean
uniform int bpStretchRestWidth;
uniform mat3 bpStretchInverse;   // Aqq^+ over the template's span (symmetric)
uniform int bpStretchSpan;       // directions the template spans, 0 to 3
uniform int bpStretchParticles;  // particles per element
uniform float bpFtleMinimumAge;  // bp::Parameters::ftleMinimumAge: younger, no FTLE
out float bpScalarVSOutput;    // the scalar, scaled to [0, 1] over the range
vec4 bpVertexMC;
vec3 bpNormalMC;
bool bpHidden; // the element, or an element of the link, was placed outside the release window
              // or terminated at the boundary

// Centre .w 1: placed outside the release window; 2: terminated (bp_reset.glsl),
// as is an element whose last test flagged it 2 (bp_test.glsl).
bool bpHiddenElement(int e)
{
  ivec2 texel = bpElementTexel(e);
  return texelFetch(bpCenters, texel, 0).w > 0.5 || texelFetch(bpElements, texel, 0).z > 1.5;
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

// The eigenvalues of the symmetric m, descending (the trigonometric closed
// form; a diagonal m as it is).
vec3 bpSymmetricEigenvalues(mat3 m)
{
  float off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
  float q = (m[0][0] + m[1][1] + m[2][2]) / 3.0;
  vec3 d = vec3(m[0][0], m[1][1], m[2][2]) - q;
  float p = sqrt((dot(d, d) + 2.0 * off) / 6.0);
  vec3 l;
  if (!(p > 1e-7 * abs(q)))
  {
    l = vec3(m[0][0], m[1][1], m[2][2]);
  }
  else
  {
    float r = clamp(determinant((m - mat3(q)) / p) * 0.5, -1.0, 1.0);
    float phi = acos(r) / 3.0;
    l.x = q + 2.0 * p * cos(phi);
    l.z = q + 2.0 * p * cos(phi + 2.0943951023931957);
    l.y = 3.0 * q - l.x - l.z;
  }
  // sorted descending
  if (l.x < l.y) l.xy = l.yx;
  if (l.y < l.z) l.yz = l.zy;
  if (l.x < l.y) l.xy = l.yx;
  return l;
}

// Element e's largest and smallest principal stretch against its template
// (bp::StretchFit::stretch): F = A Aqq^+ of its particles about their mean,
// the square roots of F^T F's eigenvalues over the span; (1, 1) for a
// template that spans nothing, a hidden element or a fit that is not finite.
// Its particles' positions are fetched here: only this colouring pays for it.
vec2 bpStretchOf(int e)
{
  if (bpStretchSpan == 0 || bpHiddenElement(e))
    return vec2(1.0);
  vec3 mean = vec3(0.0);
  for (int k = 0; k < bpStretchParticles; ++k)
    mean += texelFetch(bpPositions, bpParticleTexel(e, k), 0).xyz;
  mean /= float(bpStretchParticles);
  mat3 A = mat3(0.0);
  for (int k = 0; k < bpStretchParticles; ++k)
  {
    vec3 p = texelFetch(bpPositions, bpParticleTexel(e, k), 0).xyz - mean;
    vec3 q = texelFetch(bpStretchRest, ivec2(k % bpStretchRestWidth, k / bpStretchRestWidth), 0).xyz;
    A += outerProduct(p, q);
  }
  mat3 F = A * bpStretchInverse;
  vec3 s2 = bpSymmetricEigenvalues(transpose(F) * F);
  vec2 s = sqrt(max(vec2(s2.x, s2[bpStretchSpan - 1]), 0.0));
  return any(isnan(s)) || any(isinf(s)) ? vec2(1.0) : s;
}

// ln(largest stretch) / age (bp::elementFtle), the age being the lifetime
// the element was drawn less the one it has left; 0 where the age is not
// positive or below bpFtleMinimumAge, or anything is not finite.
float bpFtleOf(int e)
{
  vec4 element = texelFetch(bpElements, bpElementTexel(e), 0);
  float age = bpLifetimeOf(e, element.y) - element.x;
  float largest = bpStretchOf(e).x;
  if (!(age > 0.0) || !(age >= bpFtleMinimumAge) || isinf(age) || !(largest > 0.0) ||
    isinf(largest))
    return 0.0;
  float ftle = log(largest) / age;
  return isnan(ftle) || isinf(ftle) ? 0.0 : ftle;
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
    vec3 v = bpVelocitySign * texelFetch(bpSamples, texel, 0).xyz;
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
    vec3 w = bpVelocitySign * texelFetch(bpSpins, elementTexel, 0).xyz;
    return bpComponent >= 0 ? w[bpComponent] : length(w);
  }
  if (bpScalarMode == BP_COLOR_SPIN_RATIO)
    return texelFetch(bpSpins, elementTexel, 0).w;
  if (bpScalarMode == BP_COLOR_AGE)
    return bpTrail != 0 ? bpTrailAge : 0.0;
  if (bpScalarMode == BP_COLOR_STRETCH)
  {
    vec2 s = bpStretchOf(e);
    return bpComponent >= 0 ? s[bpComponent] : length(s);
  }
  if (bpScalarMode == BP_COLOR_FTLE)
    return bpFtleOf(e);
  if (bpScalarMode == BP_COLOR_SLIP || bpScalarMode == BP_COLOR_PARTICLE_VELOCITY)
  {
    vec3 v = texelFetch(bpSlips, texel, 0).xyz;
    if (bpScalarMode == BP_COLOR_PARTICLE_VELOCITY)
      v += bpVelocitySign * texelFetch(bpSamples, texel, 0).xyz;
    return bpComponent >= 0 ? v[bpComponent] : length(v);
  }
  return 0.0;
}

// Whether element e's pose in the trail slot drawn lies across a periodic
// seam from the element (bp::Domain::acrossPeriodicSeam): its first particle
// there and now farther apart than half a period along a periodic axis.
bool bpAcrossPeriodicSeam(int e)
{
  ivec2 texel = bpParticleTexel(e, 0);
  vec3 d = abs(texelFetch(bpTrailPositions, texel, 0).xyz - texelFetch(bpPositions, texel, 0).xyz);
  for (int a = 0; a < 3; ++a)
  {
    if (bpTrailHalfPeriods[a] > 0.0 && d[a] > bpTrailHalfPeriods[a])
      return true;
  }
  return false;
}

// Whether element e has no pose in the trail slot drawn: the slot holds
// another generation's (a released element starts a new trail), or none, or
// a pose from before the element moved across a periodic seam (the trail
// breaks there).
bool bpNotInTrail(int e)
{
  ivec2 elementTexel = bpElementTexel(e);
  return texelFetch(bpTrailElements, elementTexel, 0).y != texelFetch(bpElements, elementTexel, 0).y ||
    bpAcrossPeriodicSeam(e);
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
