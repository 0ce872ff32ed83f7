// Shared by every kernel of the GPU engine, after bp_shared.glsl (the
// layout) and bp_inputs.glsl. It mirrors Core/ operation for operation
// (same formulas, same order of float operations) so that the GPU engine
// matches the CPU engine to rounding. The BP_* constants are #defines made from Core/'s C++ values
// (Gpu/ShaderSource.cpp: engineConstantDefinitions).

// ---- Layout (continued from bp_shared.glsl) -------------------------------
uniform int bpElements;  // E
uniform int bpParticles; // n, particles per element

// The element of a per-element pass's texel; false outside the system.
bool bpElementOf(ivec2 texel, out int e)
{
  e = texel.y * bpElementGrid.x + texel.x;
  return e < bpElements;
}

// Element and particle index of a particle texel; false outside the system.
bool bpParticleOf(ivec2 texel, out int e, out int i)
{
  ivec2 block = texel / bpElementGrid;
  ivec2 local = texel - block * bpElementGrid;
  i = block.y * bpBlocksPerRow + block.x;
  e = local.y * bpElementGrid.x + local.x;
  return i < bpParticles && e < bpElements && block.x < bpBlocksPerRow;
}

// ---- Placement (Engine::place) --------------------------------------------
uniform vec3 bpEmitterMin;
uniform vec3 bpEmitterMax;
uniform float bpElementSize;
uniform int bpOrientation; // Parameters::orientation: BP_ORIENTATION_FIXED, _RANDOM or _ALONG_FLOW
uniform vec3 bpFrameRow0;
uniform vec3 bpFrameRow1;
uniform vec3 bpFrameRow2;
// A super set (Core/Elements/SuperSet.h) is released as one (bpLinked and
// bpDrawElement are in bp_shared.glsl): every element sits at its lattice site.
uniform sampler2D bpLatticeSites; // per element: the lattice site

// Engine::releaseCenter: candidate k of a release (candidateDraw) in the
// box [lo, hi].
vec3 bpCandidateIn(int e, float generation, int k, vec3 lo, vec3 hi)
{
  uint d = k == 0 ? 0u : BP_FURTHER_CANDIDATE_DRAW + uint(3 * (k - 1));
  vec3 u = vec3(bpDraw(e, generation, d), bpDraw(e, generation, d + 1u),
    bpDraw(e, generation, d + 2u));
  return lo + u * (hi - lo);
}

// Candidate k in the emitter box.
vec3 bpCandidate(int e, float generation, int k)
{
  return bpCandidateIn(e, generation, k, bpEmitterMin, bpEmitterMax);
}

// Where releases may not land (releaseUnfitCells), per cell of the field.
uniform usampler3D bpReleaseUnfit;
uniform bool bpReleaseMasked;

bool bpReleaseFits(vec3 c);

// A seed point fits in the field's bounds and, with a mask, in a fit cell.
bool bpSeedFits(vec3 c);

// Release centres from a seed source (Parameters::seedPoints), 256 a row.
uniform sampler2D bpSeedPoints;
uniform int bpSeedCount; // 0: the emitter box

// Release Pattern = Lattice (Core/Release/ReleaseLattice.h): element e at point e,
// x fastest; a generation's lifetime is element 0's.
// (bpLattice is in bp_shared.glsl.)
uniform ivec3 bpLatticeCounts;
uniform vec3 bpLatticeOrigin;
uniform vec3 bpLatticeSpacing;

vec3 bpLatticePoint(int e)
{
  int n = bpLatticeCounts.x * bpLatticeCounts.y * bpLatticeCounts.z;
  int r = e % max(n, 1);
  ivec3 i;
  i.x = r % bpLatticeCounts.x;
  r /= bpLatticeCounts.x;
  i.y = r % bpLatticeCounts.y;
  i.z = r / bpLatticeCounts.y;
  return bpLatticeOrigin + vec3(i) * bpLatticeSpacing;
}

// Release Weights (Core/Release/ReleaseWeights.h): (|w|, 0, 0) per grid point,
// sampled as a time step; candidate k is taken with probability w / max.
uniform sampler3D bpReleaseWeights;
uniform bool bpWeighted;
uniform float bpWeightMax;

vec3 bpSampleSlice(sampler3D field, vec3 p);

// Where weighted candidates are drawn: the emitter box cut to the weights'
// support, or the emitter box where they do not meet (weightedBox).
uniform vec3 bpWeightSupportMin;
uniform vec3 bpWeightSupportMax;

vec3 bpWeightedCenter(int e, float generation)
{
  vec3 lo = max(bpEmitterMin, bpWeightSupportMin);
  vec3 hi = min(bpEmitterMax, bpWeightSupportMax);
  if (any(greaterThan(lo, hi)))
  {
    lo = bpEmitterMin;
    hi = bpEmitterMax;
  }
  vec3 best = vec3(0.0);
  float bestWeight = -1.0;
  vec3 c;
  for (int k = 0; k < BP_RELEASE_TRIES; ++k)
  {
    c = bpCandidateIn(e, generation, k, lo, hi);
    if (!bpSeedFits(c))
    {
      continue;
    }
    float w = bpSampleSlice(bpReleaseWeights, c).x;
    // The acceptance draw weightDraw(k), after every candidate's (as bpCandidate's).
    if (bpDraw(e, generation, BP_FIRST_WEIGHT_DRAW + uint(k)) * bpWeightMax < w)
    {
      return c;
    }
    if (w > bestWeight)
    {
      bestWeight = w;
      best = c;
    }
  }
  return bestWeight >= 0.0 ? best : c;
}

vec3 bpCenterOf(int e, float generation)
{
  if (bpLinked)
  {
    return texelFetch(bpLatticeSites, bpElementTexel(e), 0).xyz;
  }
  if (bpSeedCount > 0)
  {
    // (generation * E + e) mod S in 32 bits: S <= 2^16 keeps each product
    // exact. A seed point that does not fit gives way to the next ones.
    uint S = uint(bpSeedCount);
    uint r = ((uint(generation) % S) * (uint(bpElements) % S) + uint(e) % S) % S;
    vec3 c = texelFetch(bpSeedPoints, ivec2(int(r % BP_SEED_ROW), int(r / BP_SEED_ROW)), 0).xyz;
    for (int k = 1; k < BP_RELEASE_TRIES && !bpSeedFits(c); ++k)
    {
      uint q = (r + uint(k)) % S;
      c = texelFetch(bpSeedPoints, ivec2(int(q % BP_SEED_ROW), int(q / BP_SEED_ROW)), 0).xyz;
    }
    return c;
  }
  if (bpLattice)
  {
    return bpLatticePoint(e);
  }
  if (bpWeighted)
  {
    return bpWeightedCenter(e, generation);
  }
  vec3 c = bpCandidate(e, generation, 0);
  for (int k = 1; bpReleaseMasked && k < BP_RELEASE_TRIES && !bpReleaseFits(c); ++k)
  {
    c = bpCandidate(e, generation, k);
  }
  return c;
}

// Rows of the rotation matrix of the unit quaternion (x, y, z, w)
// (quaternionToMatrix).
void bpQuaternionRows(vec4 q, out vec3 r0, out vec3 r1, out vec3 r2)
{
  float x = q.x, y = q.y, z = q.z, w = q.w;
  r0 = vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y));
  r1 = vec3(2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x));
  r2 = vec3(2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y));
}

// The matrix of rows r0, r1, r2 times v.
vec3 bpRowsTimes(vec3 r0, vec3 r1, vec3 r2, vec3 v)
{
  return vec3(r0.x * v.x + r0.y * v.y + r0.z * v.z, r1.x * v.x + r1.y * v.y + r1.z * v.z,
    r2.x * v.x + r2.y * v.y + r2.z * v.z);
}

// The Hamilton product a * b of quaternions (x, y, z, w): b, then a
// (multiplyQuaternions).
vec4 bpQuaternionProduct(vec4 a, vec4 b)
{
  return vec4(a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
    a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
    a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
    a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
}

// Position of template particle `rest` in element e of the given generation.
// A particle at `rest` of an element placed at its release centre c with the
// orientation q the reset pass chose (the frame's rows when Fixed).
vec3 bpPlace(vec3 c, vec4 q, vec3 rest)
{
  vec3 r0 = bpFrameRow0, r1 = bpFrameRow1, r2 = bpFrameRow2;
  if (bpOrientation != BP_ORIENTATION_FIXED)
  {
    // The reset pass's quaternion as a matrix.
    bpQuaternionRows(q, r0, r1, r2);
  }
  return c + bpElementSize * bpRowsTimes(r0, r1, r2, rest);
}

// ---- The field (VectorField::sample, exact trilinear by texelFetch) --------
uniform sampler3D bpField0;
uniform sampler3D bpField1;
uniform bool bpUnsteady;
uniform vec3 bpOrigin;
uniform vec3 bpInverseSpacing;
uniform vec3 bpMaxIndex;
uniform ivec3 bpNextCorner; // 1 along an axis with cells, 0 along a flat one
uniform vec3 bpLower;
uniform vec3 bpUpper;
uniform bvec3 bpDegenerate;
uniform bvec3 bpPeriodic; // periodic axes (Periodic.h), never a flat one

// Periodic.h's wrapPeriodic: x moved by whole periods into [lower, upper).
float bpWrapPeriodic(float x, float lower, float upper)
{
  if (!(x < lower || x > upper) || isinf(x) || isnan(x))
  {
    return x;
  }
  float period = upper - lower;
  float w = x - period * floor((x - lower) / period);
  if (!(w >= lower) || !(w < upper))
  {
    w = lower;
  }
  return w;
}

// Periodic.h's periodicShift along each periodic axis: the whole periods that
// bring an element's centre c back into the box; 0 elsewhere.
vec3 bpPeriodicShift(vec3 c)
{
  vec3 shift = vec3(0.0);
  for (int a = 0; a < 3; ++a)
  {
    float lower = bpLower[a], upper = bpUpper[a];
    if (bpPeriodic[a] && (c[a] < lower || c[a] > upper) && !isinf(c[a]) && !isnan(c[a]))
    {
      float period = upper - lower;
      shift[a] = -floor((c[a] - lower) / period) * period;
    }
  }
  return shift;
}

// Domain::bounded: an axis with sides, neither flat nor periodic.
bool bpBounded(int a)
{
  return !bpDegenerate[a] && !bpPeriodic[a];
}
// Rectilinear axes: row a of bpAxes holds, per point i, its coordinate and the
// inverse width of cell i (VectorField::axisTable); row 3 + a holds, per bin
// of a uniform division of the axis into bpBins[a] bins, the cell that holds
// the bin's start. Bins are at most half the narrowest cell, so a bin holds at
// most one point and the cell is found with three fetches and no search.
uniform bvec3 bpRectilinear;
uniform ivec3 bpLastCell; // points - 2
uniform ivec3 bpBins;
uniform vec3 bpBinScale; // bins per unit length
uniform sampler2D bpAxes;

// The cell along axis a that holds x, and the position within it: the cell
// VectorField::locate finds by binary search, the same weight arithmetic.
void bpLocate(int a, float x, out int cell, out float fraction)
{
  if (bpPeriodic[a])
  {
    x = bpWrapPeriodic(x, bpLower[a], bpUpper[a]); // across the seam
  }
  if (!bpRectilinear[a])
  {
    float g = (x - bpOrigin[a]) * bpInverseSpacing[a];
    g = min(max(g, 0.0), bpMaxIndex[a]);
    float i = min(floor(g), max(bpMaxIndex[a] - 1.0, 0.0));
    fraction = g - i;
    cell = int(i);
    return;
  }
  x = min(max(x, bpLower[a]), bpUpper[a]);
  int b = clamp(int((x - bpLower[a]) * bpBinScale[a]), 0, bpBins[a] - 1);
  int i = int(texelFetch(bpAxes, ivec2(b, 3 + a), 0).x);
  // The bin computed in float may be one off either way: one step down, at
  // most two up.
  if (i > 0 && texelFetch(bpAxes, ivec2(i, a), 0).x > x)
  {
    i -= 1;
  }
  if (i < bpLastCell[a] && texelFetch(bpAxes, ivec2(i + 1, a), 0).x <= x)
  {
    i += 1;
  }
  if (i < bpLastCell[a] && texelFetch(bpAxes, ivec2(i + 1, a), 0).x <= x)
  {
    i += 1;
  }
  vec2 c = texelFetch(bpAxes, ivec2(i, a), 0).xy;
  fraction = min((x - c.x) * c.y, 1.0);
  cell = i;
}

// The cell that holds p (its first corner) and the fractions within it.
ivec3 bpLocateCell(vec3 p, out vec3 f)
{
  ivec3 a;
  bpLocate(0, p.x, a.x, f.x);
  bpLocate(1, p.y, a.y, f.y);
  bpLocate(2, p.z, a.z, f.z);
  return a;
}

// The field's values at the 8 corners of the cell at `a` (its first corner),
// c[k] at offset (k & 1, (k >> 1) & 1, k >> 2); along a flat axis both
// corners are the one point.
void bpCorners(sampler3D field, ivec3 a, out vec3 c[8])
{
  ivec3 s = bpNextCorner;
  c[0] = texelFetch(field, a, 0).xyz;
  c[1] = texelFetch(field, a + ivec3(s.x, 0, 0), 0).xyz;
  c[2] = texelFetch(field, a + ivec3(0, s.y, 0), 0).xyz;
  c[3] = texelFetch(field, a + ivec3(s.x, s.y, 0), 0).xyz;
  c[4] = texelFetch(field, a + ivec3(0, 0, s.z), 0).xyz;
  c[5] = texelFetch(field, a + ivec3(s.x, 0, s.z), 0).xyz;
  c[6] = texelFetch(field, a + ivec3(0, s.y, s.z), 0).xyz;
  c[7] = texelFetch(field, a + s, 0).xyz;
}

vec3 bpSampleSlice(sampler3D field, vec3 p)
{
  vec3 f;
  ivec3 a = bpLocateCell(p, f);
  vec3 c[8];
  bpCorners(field, a, c);
  vec3 c000 = c[0], c100 = c[1], c010 = c[2], c110 = c[3];
  vec3 c001 = c[4], c101 = c[5], c011 = c[6], c111 = c[7];
  vec3 x00 = c000 + f.x * (c100 - c000);
  vec3 x10 = c010 + f.x * (c110 - c010);
  vec3 x01 = c001 + f.x * (c101 - c001);
  vec3 x11 = c011 + f.x * (c111 - c011);
  vec3 y0 = x00 + f.y * (x10 - x00);
  vec3 y1 = x01 + f.y * (x11 - x01);
  return y0 + f.z * (y1 - y0);
}

// `weight` is the second slice's weight at the sample time, computed by the host.
vec3 bpSample(vec3 p, float weight)
{
  vec3 v = bpSampleSlice(bpField0, p);
  if (bpUnsteady && weight > 0.0)
  {
    vec3 v1 = bpSampleSlice(bpField1, p);
    v += weight * (v1 - v);
  }
  return v;
}

bool bpContains(vec3 p)
{
  for (int a = 0; a < 3; ++a)
  {
    if (bpBounded(a) && !(p[a] >= bpLower[a] && p[a] <= bpUpper[a]))
    {
      return false;
    }
  }
  return true;
}

// The cells outside the flow's domain (VectorField::outsideCellAt, DomainMask.h):
// per cell's lowest corner, nonzero outside; a time step without one has none.
uniform usampler3D bpOutside0;
uniform usampler3D bpOutside1;
uniform bool bpMasked0;
uniform bool bpMasked1;

bool bpOutsideCell(vec3 p, float weight)
{
  if (!bpMasked0 && !bpMasked1)
  {
    return false;
  }
  vec3 f;
  ivec3 a = bpLocateCell(p, f);
  return (bpMasked0 && texelFetch(bpOutside0, a, 0).r != 0u) ||
    (weight > 0.0 && bpMasked1 && texelFetch(bpOutside1, a, 0).r != 0u);
}

// ---- The field's curl (VectorField::sampleWithCurl) ------------------------
// d[a][k] = d v_k / d x_a in the cell at `a` (its first corner) with
// fractions f; w[a] is the fraction's derivative along axis a.
void bpGradient(sampler3D field, ivec3 a, vec3 f, vec3 w, out vec3 d[3])
{
  vec3 c[8];
  bpCorners(field, a, c);
  vec3 c000 = c[0], c100 = c[1], c010 = c[2], c110 = c[3];
  vec3 c001 = c[4], c101 = c[5], c011 = c[6], c111 = c[7];
  vec3 x0 = (c100 - c000) + f.y * ((c110 - c010) - (c100 - c000));
  vec3 x1 = (c101 - c001) + f.y * ((c111 - c011) - (c101 - c001));
  d[0] = (x0 + f.z * (x1 - x0)) * w.x;
  vec3 y0 = (c010 - c000) + f.x * ((c110 - c100) - (c010 - c000));
  vec3 y1 = (c011 - c001) + f.x * ((c111 - c101) - (c011 - c001));
  d[1] = (y0 + f.z * (y1 - y0)) * w.y;
  vec3 z0 = (c001 - c000) + f.x * ((c101 - c100) - (c001 - c000));
  vec3 z1 = (c011 - c010) + f.x * ((c111 - c110) - (c011 - c010));
  d[2] = (z0 + f.y * (z1 - z0)) * w.z;
}

// The fractions' derivatives along each axis in the cell at `a`
// (VectorField::locateWithSlopes): 0 along a flat axis (its inverse spacing
// is 0), where nothing varies.
vec3 bpSlopes(ivec3 a)
{
  vec3 w;
  for (int k = 0; k < 3; ++k)
  {
    w[k] = bpRectilinear[k] ? texelFetch(bpAxes, ivec2(a[k], k), 0).y : bpInverseSpacing[k];
  }
  return w;
}

// The gradient d[a][c] = dv_c/dx_a of the trilinear interpolant in the cell
// that holds p, each time step's blended with `weight` as bpSample blends
// the values (VectorField::blendedGradient).
void bpBlendedGradient(vec3 p, float weight, out vec3 d[3])
{
  vec3 f;
  ivec3 a = bpLocateCell(p, f);
  vec3 w = bpSlopes(a);
  bpGradient(bpField0, a, f, w, d);
  if (bpUnsteady && weight > 0.0)
  {
    vec3 d1[3];
    bpGradient(bpField1, a, f, w, d1);
    for (int k = 0; k < 3; ++k)
    {
      d[k] += weight * (d1[k] - d[k]);
    }
  }
}

// curl v at p, from bpBlendedGradient. Used by the colouring samples and the
// pose pass's vorticity meter.
vec3 bpCurl(vec3 p, float weight)
{
  vec3 d[3];
  bpBlendedGradient(p, weight, d);
  return vec3(d[1][2] - d[2][1], d[2][0] - d[0][2], d[0][1] - d[1][0]);
}

bool bpReleaseFits(vec3 c)
{
  vec3 f;
  ivec3 a = bpLocateCell(c, f);
  return bpContains(c) && texelFetch(bpReleaseUnfit, a, 0).r == 0u;
}

bool bpSeedFits(vec3 c)
{
  return bpContains(c) && (!bpReleaseMasked || bpReleaseFits(c));
}

// Engine::inDomain: in the bounds and in a cell inside the flow's domain.
bool bpInDomain(vec3 p, float weight)
{
  return bpContains(p) && !bpOutsideCell(p, weight);
}

bool bpFinite(vec3 p)
{
  return !any(isnan(p)) && !any(isinf(p));
}

// ---- Walls (Core/Engine/Walls.h; engine specification 2.8, "Walls") -------
// With Boundary Stick, Slip or Bounce the sides of the domain box (along
// axes that are not flat) keep every particle in. Sides met are bits: 2a
// for the lower side of axis a, 2a + 1 for the upper (WallHits).
uniform int bpBoundary;      // a bp::Boundary
uniform float bpRestitution; // Bounce's e, in [0, 1]

bool bpWalled()
{
  return bpBoundary == BP_BOUNDARY_STICK || bpBoundary == BP_BOUNDARY_SLIP ||
    bpBoundary == BP_BOUNDARY_BOUNCE;
}

// ---- The walls of the cells outside the flow (MaskWalls.h) ----------------
// The faces between a cell inside the flow and one outside it, normal to the
// grid's axes: Boundary Stick, Slip and Bounce keep particles off them by
// bpWallOffset (surfaceWallOffset of the field's domain, computed on the
// host; also the Surfaces' Walls' offset).
uniform float bpWallOffset;

// VectorField::outsideCellIndexed: cell c (its first corner) outside the flow.
bool bpOutsideCellIndexed(ivec3 c, float weight)
{
  return (bpMasked0 && texelFetch(bpOutside0, c, 0).r != 0u) ||
    (weight > 0.0 && bpMasked1 && texelFetch(bpOutside1, c, 0).r != 0u);
}

// VectorField::pointCoordinate: point i's coordinate along axis a.
float bpPointCoordinate(int a, int i)
{
  return bpRectilinear[a] ? texelFetch(bpAxes, ivec2(i, a), 0).x
                          : bpOrigin[a] + float(i) / bpInverseSpacing[a];
}

// firstOutsideFace: the first face from -> to crosses into a cell outside
// the flow: its axis (-1 for none), plane, normal toward `from` along the
// axis (+1 or -1), point, and the cell inside the flow it leaves.
int bpFirstOutsideFace(vec3 from, vec3 to, float weight, out float plane, out float toward,
  out vec3 point, out ivec3 left)
{
  plane = 0.0;
  toward = 0.0;
  point = from;
  vec3 f;
  ivec3 cell = bpLocateCell(from, f);
  left = cell;
  for (int a = 0; a < 3; ++a)
  {
    if (bpPeriodic[a] && !(from[a] >= bpLower[a] && from[a] <= bpUpper[a] &&
                           to[a] >= bpLower[a] && to[a] <= bpUpper[a]))
    {
      return -1; // across a periodic side: no face
    }
  }
  ivec3 end = bpLocateCell(to, f);
  if (bpOutsideCellIndexed(cell, weight))
  {
    return -1;
  }
  for (int k = 0; k < BP_MASK_WALL_CROSSINGS; ++k)
  {
    int axis = -1, step = 0;
    float first = 0.0, w0 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      if (cell[a] == end[a])
      {
        continue;
      }
      int s = end[a] > cell[a] ? 1 : -1;
      float w = bpPointCoordinate(a, s > 0 ? cell[a] + 1 : cell[a]);
      float d = to[a] - from[a];
      float t = d != 0.0 ? min(max((w - from[a]) / d, 0.0), 1.0) : 0.0;
      if (axis < 0 || t < first)
      {
        axis = a;
        step = s;
        first = t;
        w0 = w;
      }
    }
    if (axis < 0)
    {
      return -1;
    }
    left = cell;
    cell[axis] += step;
    if (bpOutsideCellIndexed(cell, weight))
    {
      plane = w0;
      toward = float(-step);
      point = from + first * (to - from);
      point[axis] = w0;
      return axis;
    }
  }
  return -1;
}

// wallOnOutsideCells for Boundary `boundary`: p, advected from `before`,
// back inside the flow on the faces; the faces met as the sides' bits, or
// BP_WALL_MASKED_CELL where no face is found (p back at `before`).
int bpWallOnOutsideCells(int boundary, vec3 before, inout vec3 p, float weight)
{
  if (!bpOutsideCell(p, weight))
  {
    return 0;
  }
  vec3 from = before, last = before;
  int hits = 0;
  for (int k = 0; k < BP_MASK_WALL_RULES; ++k)
  {
    float plane, toward;
    vec3 point;
    ivec3 left;
    int a = bpFirstOutsideFace(from, p, weight, plane, toward, point, left);
    if (a < 0)
    {
      p = last;
      return hits != 0 ? hits : BP_WALL_MASKED_CELL;
    }
    float inside = plane + bpWallOffset * toward;
    last = point;
    last[a] = inside;
    for (int j = 0; j < 3; ++j)
    {
      if (j != a && bpBounded(j))
      {
        float lo = bpPointCoordinate(j, left[j]) + bpWallOffset;
        float hi = bpPointCoordinate(j, left[j] + 1) - bpWallOffset;
        last[j] = min(max(last[j], lo), hi);
      }
    }
    hits |= 1 << (2 * a + (toward < 0.0 ? 1 : 0));
    if (boundary == BP_BOUNDARY_STICK)
    {
      p = last;
      return hits;
    }
    float beyond = abs(p[a] - plane);
    p[a] = boundary == BP_BOUNDARY_BOUNCE
      ? plane + toward * max(bpRestitution * beyond, bpWallOffset)
      : inside;
    if (!bpOutsideCell(p, weight))
    {
      return hits;
    }
    from = last;
  }
  p = last;
  return hits;
}

// onOutsideFace: p, in a cell inside the flow, within two offsets of a face
// of its cell whose neighbour across it is outside the flow.
bool bpOnOutsideFace(vec3 p, float weight)
{
  if ((!bpMasked0 && !bpMasked1) || !bpFinite(p))
  {
    return false;
  }
  vec3 f;
  ivec3 cell = bpLocateCell(p, f);
  if (bpOutsideCellIndexed(cell, weight))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (bpDegenerate[a])
    {
      continue;
    }
    ivec3 next = cell;
    next[a] = cell[a] - 1;
    float below = p[a] - bpPointCoordinate(a, cell[a]);
    if (cell[a] > 0 && below >= 0.0 && below <= 2.0 * bpWallOffset &&
      bpOutsideCellIndexed(next, weight))
    {
      return true;
    }
    next[a] = cell[a] + 1;
    float above = bpPointCoordinate(a, cell[a] + 1) - p[a];
    if (cell[a] < bpLastCell[a] && above >= 0.0 && above <= 2.0 * bpWallOffset &&
      bpOutsideCellIndexed(next, weight))
    {
      return true;
    }
  }
  return false;
}

// onWall: p on a side, compared exactly.
bool bpOnWall(vec3 p)
{
  for (int a = 0; a < 3; ++a)
  {
    if (bpBounded(a) && (p[a] == bpLower[a] || p[a] == bpUpper[a]))
    {
      return true;
    }
  }
  return false;
}

// Whether p lies on a Wall of the Surfaces (below): Stick holds it too.
bool bpOnSurfaceWall(vec3 p);

// A particle Stick holds: not advected, back where it was after restoration:
// on a side, on a face of the cells outside the flow (at `weight`), or on a
// Wall of the Surfaces (Engine::heldOnSurfaceWall).
bool bpHeld(vec3 p, float weight)
{
  return bpBoundary == BP_BOUNDARY_STICK &&
    (bpOnWall(p) || bpOnOutsideFace(p, weight) || bpOnSurfaceWall(p));
}

// clampToBox: p put on the sides it lies beyond; the sides met.
int bpClampToBox(inout vec3 p)
{
  int hits = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (!bpBounded(a))
    {
      continue;
    }
    if (p[a] < bpLower[a])
    {
      p[a] = bpLower[a];
      hits |= 1 << (2 * a);
    }
    else if (p[a] > bpUpper[a])
    {
      p[a] = bpUpper[a];
      hits |= 1 << (2 * a + 1);
    }
  }
  return hits;
}

// Stick from a `before` in the box: the first point of before -> p on a side.
int bpStickAlongStep(vec3 before, inout vec3 p)
{
  float first = 1.0;
  int axis = -1;
  float wall = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    if (!bpBounded(a))
    {
      continue;
    }
    float w = p[a] < bpLower[a] ? bpLower[a] : p[a] > bpUpper[a] ? bpUpper[a] : p[a];
    if (w == p[a])
    {
      continue;
    }
    float t = (w - before[a]) / (p[a] - before[a]);
    if (axis < 0 || t < first)
    {
      first = t;
      axis = a;
      wall = w;
    }
  }
  if (axis < 0)
  {
    return 0;
  }
  vec3 q;
  for (int a = 0; a < 3; ++a)
  {
    q[a] = a == axis ? wall : before[a] + first * (p[a] - before[a]);
  }
  p = q;
  int hit = 1 << (2 * axis + (wall == bpUpper[axis] ? 1 : 0));
  return hit | bpClampToBox(p);
}

// wallAfterAdvection for Boundary bpBoundary.
int bpWallAfterAdvection(vec3 before, inout vec3 p)
{
  if (bpBoundary == BP_BOUNDARY_STICK)
  {
    return bpContains(before) ? bpStickAlongStep(before, p) : bpClampToBox(p);
  }
  if (bpBoundary == BP_BOUNDARY_SLIP)
  {
    return bpClampToBox(p);
  }
  int hits = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (!bpBounded(a))
    {
      continue;
    }
    if (p[a] < bpLower[a])
    {
      p[a] = bpLower[a] + bpRestitution * (bpLower[a] - p[a]);
      hits |= 1 << (2 * a);
    }
    else if (p[a] > bpUpper[a])
    {
      p[a] = bpUpper[a] - bpRestitution * (p[a] - bpUpper[a]);
      hits |= 1 << (2 * a + 1);
    }
  }
  return hits | bpClampToBox(p);
}

// Engine::wallParticle's positions: p, advected from `before`, back into
// the box, and off the faces of the cells outside the flow (at the weight
// `weight` of the step's end; bpWallOnOutsideCells). Returns the sides and
// faces met, with BP_WALL_MASKED_CELL where it went back to `before` (no
// face found; the advected texture's .w carries it to the slip share pass).
int bpWallParticle(vec3 before, inout vec3 p, float weight)
{
  if (!bpFinite(p))
  {
    return 0;
  }
  int hits = bpWallAfterAdvection(before, p);
  return hits | bpWallOnOutsideCells(bpBoundary, before, p, weight);
}

// wallVelocity on a heavy particle's slip s at its walled position p: the
// rule acts on v = u + s, u the flow there at the step's end.
vec3 bpWallSlip(int hits, vec3 p, vec3 s, float weight)
{
  if (hits == 0)
  {
    return s;
  }
  vec3 u = bpSample(p, weight);
  vec3 v = u + s;
  if ((hits & BP_WALL_MASKED_CELL) != 0 || bpBoundary == BP_BOUNDARY_STICK)
  {
    v = vec3(0.0);
  }
  else
  {
    for (int a = 0; a < 3; ++a)
    {
      bool lower = (hits & (1 << (2 * a))) != 0;
      bool upper = (hits & (1 << (2 * a + 1))) != 0;
      if ((lower && v[a] < 0.0) || (upper && v[a] > 0.0))
      {
        v[a] = bpBoundary == BP_BOUNDARY_BOUNCE ? -bpRestitution * v[a] : 0.0;
      }
    }
  }
  return v - u;
}

// Engine::wallAfterRestoration for one particle restored to q from its
// walled advected position a: a held one back at a, another kept in the
// box and out of cells outside the flow (Slip's rule on their faces from a).
vec3 bpWallRestored(vec3 q, vec3 a, float weight)
{
  if (bpHeld(a, weight))
  {
    return a;
  }
  bpClampToBox(q);
  if (bpFinite(q))
  {
    bpWallOnOutsideCells(BP_BOUNDARY_SLIP, a, q, weight);
  }
  return q;
}

// ---- Walls of the Surfaces (engine specification 2.10) --------------------
// The Surfaces' Wall triangles (SurfaceSet::wallCorners): bpWallCount of
// them, 0 where there are none (then nothing here is read). Corner c of
// triangle k is texel (3 (k % BP_OUTLET_ROW) + c, k / BP_OUTLET_ROW) of
// bpWalls, laid out as bpOutlets (bp_test.glsl). bpWallOffset is
// surfaceWallOffset of the field's domain, computed on the host.
uniform int bpWallCount;
uniform sampler2D bpWalls;

vec3 bpWallCorner(int k, int c)
{
  return texelFetch(bpWalls, ivec2(3 * (k % BP_OUTLET_ROW) + c, k / BP_OUTLET_ROW), 0).xyz;
}

// Where the step a + t d meets the triangle (v, v1, v2), t in (0, 1]; -1
// where it does not: SurfaceCrossings' meet (Moller-Trumbore) in float,
// closed on the edges (BP_OUTLET_EDGE_SLACK). The Walls' and the Outlets'.
float bpMeetTriangle(vec3 v, vec3 v1, vec3 v2, vec3 a, vec3 d)
{
  vec3 e1 = v1 - v, e2 = v2 - v;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  if (det == 0.0 || !bpFinite(vec3(det)))
  {
    return -1.0;
  }
  vec3 s = a - v;
  float u = dot(s, p) / det;
  if (!(u >= -BP_OUTLET_EDGE_SLACK && u <= 1.0 + BP_OUTLET_EDGE_SLACK))
  {
    return -1.0;
  }
  vec3 q = cross(s, e1);
  float w = dot(d, q) / det;
  if (!(w >= -BP_OUTLET_EDGE_SLACK && u + w <= 1.0 + BP_OUTLET_EDGE_SLACK))
  {
    return -1.0;
  }
  float t = dot(e2, q) / det;
  return t > 0.0 && t <= 1.0 ? t : -1.0;
}

// Where the step a + t d meets Wall triangle k (bpMeetTriangle).
float bpMeetWall(int k, vec3 a, vec3 d)
{
  return bpMeetTriangle(bpWallCorner(k, 0), bpWallCorner(k, 1), bpWallCorner(k, 2), a, d);
}

// SurfaceCrossings::firstCrossing over the Walls: the smallest t of the
// step a -> b's crossings, the first triangle on a tie (`first`, -1 and
// t 2 where it crosses none, or a or b is not finite).
float bpFirstWallCrossing(vec3 a, vec3 b, out int first)
{
  first = -1;
  float best = 2.0;
  if (!bpFinite(a) || !bpFinite(b))
  {
    return best;
  }
  vec3 d = b - a;
  for (int k = 0; k < bpWallCount; ++k)
  {
    float t = bpMeetWall(k, a, d);
    if (t > 0.0 && t < best)
    {
      best = t;
      first = k;
    }
  }
  return best;
}

// SurfaceSet::onWall at the distance Engine::restingOnWall (2 bpWallOffset):
// p within it of a Wall triangle's plane, its foot on the plane within the
// triangle (SurfaceCrossings::lies in float; the edges closed with the slack
// of bpMeetWall, so that a particle Stick put where a step met a triangle
// lies on it). Reads nothing where there are no Walls.
bool bpOnSurfaceWall(vec3 p)
{
  if (bpWallCount == 0 || !bpFinite(p))
  {
    return false;
  }
  float distance = 2.0 * bpWallOffset;
  for (int k = 0; k < bpWallCount; ++k)
  {
    vec3 v = bpWallCorner(k, 0);
    vec3 e1 = bpWallCorner(k, 1) - v, e2 = bpWallCorner(k, 2) - v;
    vec3 n = cross(e1, e2);
    float area2 = dot(n, n);
    vec3 s = p - v;
    float height = dot(s, n) / sqrt(area2);
    if (!(abs(height) <= distance))
    {
      continue;
    }
    // The foot's barycentric coordinates: (s x e2).n and (e1 x s).n over |n|^2.
    float u = dot(cross(s, e2), n) / area2;
    float w = dot(cross(e1, s), n) / area2;
    if (u >= -BP_OUTLET_EDGE_SLACK && w >= -BP_OUTLET_EDGE_SLACK &&
      u + w <= 1.0 + BP_OUTLET_EDGE_SLACK)
    {
      return true;
    }
  }
  return false;
}

// Wall triangle k's unit normal (its corners' right hand), turned to the
// side the step d came from (towardStart); `along`: d went the normal's way.
vec3 bpWallTowardStart(int k, vec3 d, out bool along)
{
  vec3 v = bpWallCorner(k, 0);
  vec3 n = cross(bpWallCorner(k, 1) - v, bpWallCorner(k, 2) - v);
  along = dot(d, n) > 0.0;
  n = n / sqrt(dot(n, n));
  return along ? -n : n;
}

// Whether the Walls act on the particles (Boundary Stick, Slip or Bounce),
// as Engine::wallsParticlesOnSurfaces; with Release Again or Terminate they
// end elements (bp_test.glsl).
bool bpWallsParticles()
{
  return bpWallCount > 0 && bpWalled();
}

// Engine::wallRule: p off the Wall triangle k its step d met at c (m the
// normal turned to the step's start): Stick puts it at c + offset m (held
// there from then on); Slip and Bounce move it by (offset - k beyond) m, k 1
// (Slip) or 1 + e (Bounce), beyond = (p - c).m.
vec3 bpWallRule(vec3 c, vec3 m, vec3 p)
{
  if (bpBoundary == BP_BOUNDARY_STICK)
  {
    return c + bpWallOffset * m;
  }
  float beyond = dot(p - c, m);
  float back = (bpBoundary == BP_BOUNDARY_BOUNCE ? 1.0 + bpRestitution : 1.0) * beyond;
  return p + (bpWallOffset - back) * m;
}

// wallAgain (EngineSurfaces.cpp): the Wall the move a -> p crosses, where a
// rule left p (`again`, -1 and t 2 where none; its t along the segment from
// a). Where the step met a Wall at an edge it shares with another, a (an
// offset off the first) lies on the other's plane or just behind it: where
// the move from a meets none, it is tested again from half an offset behind
// a (a moved there), a crossing so found taken only where `before` lies on
// the side the rule keeps p.
float bpWallAgain(vec3 before, inout vec3 a, vec3 p, out int again)
{
  float t = bpFirstWallCrossing(a, p, again);
  if (again >= 0)
  {
    return t;
  }
  vec3 d = p - a;
  float len = sqrt(dot(d, d));
  if (!(len > 0.0))
  {
    return t;
  }
  vec3 from = a - (0.5 * bpWallOffset / len) * d;
  t = bpFirstWallCrossing(from, p, again);
  if (again < 0)
  {
    return t;
  }
  bool along;
  vec3 m = bpWallTowardStart(again, p - from, along);
  vec3 c = from + t * (p - from);
  if (!(dot(before, m) - dot(c, m) > 0.0))
  {
    again = -1;
    return 2.0;
  }
  a = from;
  return t;
}

// keptOnSide (EngineSurfaces.cpp): p reached from `before` without crossing
// a Wall. Where the segment before -> p crosses one (a rule's start behind
// the other Wall at an edge sharper than a right angle), p goes back along
// it to an offset short of that crossing (before itself where closer).
vec3 bpKeptOnSide(vec3 before, vec3 p)
{
  int last;
  float t = bpFirstWallCrossing(before, p, last);
  if (last < 0)
  {
    return p;
  }
  vec3 c = before + t * (p - before);
  vec3 back = before - c;
  float length = sqrt(dot(back, back));
  float share = length > bpWallOffset ? bpWallOffset / length : 1.0;
  return c + share * back;
}

// Engine::wallParticleOnSurfaces's positions: p, advected from `before`
// and walled by the field's sides, off the first Wall its step crosses
// (tested from half an offset behind `before`, so that a particle on a
// Wall's plane meets it; at c, m the normal turned to the start's side) by
// bpWallRule; then (Slip, Bounce: Stick stays where the step met the Wall),
// where the walls bend inward (or the step went through an edge), the rule
// again on each Wall the move from the last one (from its crossing +
// offset m) crosses (bpWallAgain), at most three times, a fourth crossing
// putting p on it, offset off.
// Returns 0 where it crosses none, else 1 + 2 k + (1 where the step went
// the normal's way): the wall met, for bpWallSlipOnSurfaces.
int bpWallOnSurfaces(vec3 before, inout vec3 p)
{
  vec3 d = p - before;
  float len = sqrt(dot(d, d));
  if (!(len > 0.0))
  {
    return 0;
  }
  vec3 from = before - (0.5 * bpWallOffset / len) * d;
  int k;
  float t = bpFirstWallCrossing(from, p, k);
  if (k < 0)
  {
    return 0;
  }
  vec3 step = p - from;
  vec3 c = from + t * step;
  bool along;
  vec3 m = bpWallTowardStart(k, step, along);
  p = bpWallRule(c, m, p);
  vec3 start = c + bpWallOffset * m;
  for (int pass = 0; pass < 4 && bpBoundary != BP_BOUNDARY_STICK; ++pass)
  {
    int again;
    vec3 a = start;
    float t2 = bpWallAgain(before, a, p, again);
    if (again < 0)
    {
      break;
    }
    vec3 d2 = p - a;
    bool along2;
    vec3 m2 = bpWallTowardStart(again, d2, along2);
    vec3 c2 = a + t2 * d2;
    if (pass == 3)
    {
      p = c2 + bpWallOffset * m2;
      break;
    }
    p = bpWallRule(c2, m2, p);
    start = c2 + bpWallOffset * m2;
  }
  if (bpBoundary != BP_BOUNDARY_STICK)
  {
    p = bpKeptOnSide(before, p);
  }
  return 1 + 2 * k + (along ? 1 : 0);
}

// The heavy particle's rule at a Wall met (`met`, bpWallOnSurfaces's
// return; 0 none): v = u + s, u the flow at its walled p at the step's end
// (`weight`): stopped (Stick, v = 0), or where v.m < 0 its part along m
// removed (Slip) or reversed times e (Bounce); the new slip v - u.
vec3 bpWallSlipOnSurfaces(int met, vec3 p, vec3 s, float weight)
{
  if (met == 0)
  {
    return s;
  }
  int k = (met - 1) / 2;
  vec3 v0 = bpWallCorner(k, 0);
  vec3 n = cross(bpWallCorner(k, 1) - v0, bpWallCorner(k, 2) - v0);
  n = n / sqrt(dot(n, n));
  vec3 m = (met - 1) - 2 * k == 1 ? -n : n;
  vec3 u = bpSample(p, weight);
  if (bpBoundary == BP_BOUNDARY_STICK)
  {
    return -u;
  }
  vec3 v = u + s;
  float into = dot(v, m);
  float turn = into < 0.0 ? (bpBoundary == BP_BOUNDARY_BOUNCE ? 1.0 + bpRestitution : 1.0) * into
                          : 0.0;
  return v - turn * m - u;
}

// Engine::keepOffSurfaceWalls for one particle restored to q from its
// advected (and walled) position a: where the move a -> q crosses a Wall,
// on that crossing, bpWallOffset off it on a's side.
vec3 bpWallRestoredOnSurfaces(vec3 q, vec3 a)
{
  int k;
  float t = bpFirstWallCrossing(a, q, k);
  if (k < 0)
  {
    return q;
  }
  vec3 d = q - a;
  bool along;
  vec3 m = bpWallTowardStart(k, d, along);
  return bpKeptOnSide(a, (a + t * d) + bpWallOffset * m);
}

// ---- Springs (Engine::restore, Engine::restoreLinks) -----------------------
// The force term of a spring between the particles at pa and pb, f (pa - pb)
// with f = stiffness (rest - |pa - pb|) / |pa - pb|; false, with none, where
// the two coincide. Each kernel scales it by the particle's share. The one
// GLSL definition, springForce in Core/Elements/SpringForce.h the one C++ one.
bool bpSpringForce(vec3 pa, vec3 pb, float rest, float stiffness, out vec3 force)
{
  vec3 d = pa - pb;
  float len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (len > 0.0)
  {
    float f = stiffness * (rest - len) / len;
    force = f * d;
    return true;
  }
  force = vec3(0.0);
  return false;
}

// ---- The rotation fit (Core/Elements/ShapeMatching.h) -------------------------------
// The largest float: a larger (or NaN) squared step is no step.
const float bpLargestFloat = 3.40282347e38;

// fitTerms: P = sum_c r_c a_c^T, by rows, and g = sum_c r_c x a_c over the
// columns of R and A.
void bpFitTerms(vec3 r0, vec3 r1, vec3 r2, vec3 a0, vec3 a1, vec3 a2, out vec3 p0, out vec3 p1,
  out vec3 p2, out vec3 g)
{
  g = vec3(0.0);
  p0 = vec3(0.0);
  p1 = vec3(0.0);
  p2 = vec3(0.0);
  for (int c = 0; c < 3; ++c)
  {
    vec3 r = vec3(r0[c], r1[c], r2[c]);
    vec3 a = vec3(a0[c], a1[c], a2[c]);
    g.x += r.y * a.z - r.z * a.y;
    g.y += r.z * a.x - r.x * a.z;
    g.z += r.x * a.y - r.y * a.x;
    p0 += r.x * a;
    p1 += r.y * a;
    p2 += r.z * a;
  }
}

// newtonTurn: (w / 2, 1) with w = H^-1 g, H = tr(P) I - sym(P) (+ damping)
// solved by H's cofactors, cut to BP_MAX_NEWTON_STEP; false where H is not
// positive definite or w is not finite.
bool bpNewtonTurn(vec3 p0, vec3 p1, vec3 p2, vec3 g, out vec4 turn)
{
  turn = vec4(0.0, 0.0, 0.0, 1.0);
  float trace = p0.x + p1.y + p2.z;
  float d = trace + BP_ROTATION_DAMPING * abs(trace);
  float h00 = d - p0.x, h11 = d - p1.y, h22 = d - p2.z;
  float h01 = -0.5 * (p0.y + p1.x), h02 = -0.5 * (p0.z + p2.x), h12 = -0.5 * (p1.z + p2.y);
  float c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
  float c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
  float det = h00 * c00 + h01 * c01 + h02 * c02;
  if (!(det > 0.0 && h00 > 0.0 && c22 > 0.0)) // Sylvester's criterion
  {
    return false;
  }
  float halfInverse = 0.5 / det; // "half" is reserved in GLSL
  turn.x = (c00 * g.x + c01 * g.y + c02 * g.z) * halfInverse;
  turn.y = (c01 * g.x + c11 * g.y + c12 * g.z) * halfInverse;
  turn.z = (c02 * g.x + c12 * g.y + c22 * g.z) * halfInverse;
  float w2 = turn.x * turn.x + turn.y * turn.y + turn.z * turn.z;
  float longest = 0.5 * BP_MAX_NEWTON_STEP;
  if (!(w2 <= longest * longest))
  {
    if (!(w2 <= bpLargestFloat))
    {
      return false;
    }
    float cut = longest / sqrt(w2);
    turn.x = turn.x * cut;
    turn.y = turn.y * cut;
    turn.z = turn.z * cut;
  }
  return true;
}

// axisTurn: the turn about g by atan2(|g|, tr(P) - n.Pn), n = g / |g|, the
// angle that fits best about that axis; false where g is 0 or not finite.
bool bpAxisTurn(vec3 p0, vec3 p1, vec3 p2, vec3 g, out vec4 turn)
{
  turn = vec4(0.0, 0.0, 0.0, 1.0);
  float g2 = g.x * g.x + g.y * g.y + g.z * g.z;
  if (!(g2 > 0.0 && g2 <= bpLargestFloat))
  {
    return false;
  }
  float length = sqrt(g2);
  float gPg = 0.0;
  gPg += g.x * (p0.x * g.x + p0.y * g.y + p0.z * g.z);
  gPg += g.y * (p1.x * g.x + p1.y * g.y + p1.z * g.z);
  gPg += g.z * (p2.x * g.x + p2.y * g.y + p2.z * g.z);
  float angle = atan(length * g2, (p0.x + p1.y + p2.z) * g2 - gPg);
  float s = sin(0.5 * angle) / length;
  turn = vec4(g.x * s, g.y * s, g.z * s, cos(0.5 * angle));
  return true;
}

// fitRotation: `iterations` steps of q towards the rotation R closest to A,
// given by its rows (the maximum of tr(R^T A)), for shape matching and the
// pose fit alike: Newton's (bpNewtonTurn) where it applies, else the best
// turn about the gradient (bpAxisTurn). A zero (or non-finite) A keeps q.
vec4 bpFitRotation(vec3 a0, vec3 a1, vec3 a2, vec4 q, int iterations)
{
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    vec3 r0, r1, r2, p0, p1, p2, g;
    vec4 turn;
    bpQuaternionRows(q, r0, r1, r2);
    bpFitTerms(r0, r1, r2, a0, a1, a2, p0, p1, p2, g);
    if (!bpNewtonTurn(p0, p1, p2, g, turn) && !bpAxisTurn(p0, p1, p2, g, turn))
    {
      break;
    }
    // q = turn * q, then normalised.
    vec4 n = bpQuaternionProduct(turn, q);
    float length = sqrt(n.x * n.x + n.y * n.y + n.z * n.z + n.w * n.w);
    q = vec4(n.x / length, n.y / length, n.z / length, n.w / length);
  }
  return q;
}

// ---- Poses and spins (Core/Elements/Pose.h) ------------------------------------------

// momentOf: the centre c of element e's particles (bpPositionOf) and their
// moment A = sum (x_i - c)(s r_i)^T against the rest shape, by rows.
void bpMomentOf(int e, out vec3 c, out vec3 a0, out vec3 a1, out vec3 a2)
{
  c = vec3(0.0);
  for (int i = 0; i < bpParticles; ++i)
  {
    c += bpPositionOf(e, i);
  }
  c = c / float(bpParticles);
  a0 = vec3(0.0);
  a1 = vec3(0.0);
  a2 = vec3(0.0);
  for (int i = 0; i < bpParticles; ++i)
  {
    vec3 d = bpPositionOf(e, i) - c;
    vec3 q = bpElementSize * texelFetch(bpRest, ivec2(i, 0), 0).xyz;
    a0 += d.x * q;
    a1 += d.y * q;
    a2 += d.z * q;
  }
}

// spinBetween: the angular velocity that turns `before` into `after` in time
// h, the short way round.
vec3 bpSpinBetween(vec4 before, vec4 after, float h)
{
  vec4 d = bpQuaternionProduct(after, vec4(-before.x, -before.y, -before.z, before.w));
  if (d.w < 0.0)
  {
    d = -d;
  }
  float s = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  float rate = s > 0.0 ? 2.0 * atan(s, d.w) / (s * h) : 0.0;
  return vec3(d.x * rate, d.y * rate, d.z * rate);
}

// spinVorticityRatio: 2 (spin . curl) / |curl|^2, 0 where |curl| h is below
// the meter's floor (or not finite), clamped to +-BP_MAX_SPIN_VORTICITY_RATIO.
float bpSpinVorticityRatio(vec3 spin, vec3 curl, float h)
{
  float c2 = curl.x * curl.x + curl.y * curl.y + curl.z * curl.z;
  float lowest = BP_MIN_VORTICITY_STEP / h;
  if (!(c2 >= lowest * lowest))
  {
    return 0.0;
  }
  float ratio = 2.0 * (spin.x * curl.x + spin.y * curl.y + spin.z * curl.z) / c2;
  return max(-BP_MAX_SPIN_VORTICITY_RATIO, min(BP_MAX_SPIN_VORTICITY_RATIO, ratio));
}
