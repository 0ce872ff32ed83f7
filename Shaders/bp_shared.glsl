// What the GPU engine's passes and the draw shader share: where an element
// and a particle sit in the engine's textures, a particle's normal from its
// triangles, and the lifetime an element is drawn (the draw's age colouring). A pass has it before bp_common.glsl (Gpu/ShaderSource.cpp);
// Gpu/CMakeLists.txt puts it before bp_draw_vs_dec.glsl in the embedded
// bpShaderDrawVSDec, since VTK compiles the draw shader on its own.

// ---- Layout ---------------------------------------------------------------
// Elements: a W x H grid, element e at (e % W, e / W).
// Particles: one such grid ("block") per template particle index i; blocks sit
// bx per row (thesis §3.5.1 strip layout, generalised to a near-square texture).
uniform ivec2 bpElementGrid; // W, H
uniform int bpBlocksPerRow;  // bx

ivec2 bpElementTexel(int e)
{
  return ivec2(e % bpElementGrid.x, e / bpElementGrid.x);
}

ivec2 bpParticleTexel(int e, int i)
{
  ivec2 block = ivec2(i % bpBlocksPerRow, i / bpBlocksPerRow);
  return block * bpElementGrid + bpElementTexel(e);
}

// ---- Normals (bp::elementNormals in Core/Elements/ElementNormals.cpp) ----------------
// A particle's normal is the normalised sum of the unit normals of the
// triangles it is a corner of, added in triangle order; (0, 0, 1) where the
// sum is zero. The cross product and lengths are written out as the CPU
// engine writes them, so the bits match.

// Adds the unit normal of triangle (a, b, c) to `sum`; a degenerate one adds nothing.
void bpAddTriangleNormal(inout vec3 sum, vec3 a, vec3 b, vec3 c)
{
  vec3 u = b - a, v = c - a;
  vec3 x = vec3(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x);
  float len = sqrt(x.x * x.x + x.y * x.y + x.z * x.z);
  if (len > 0.0)
  {
    sum += x / len;
  }
}

// The normal from the sum of its triangles' unit normals.
vec3 bpNormalOfSum(vec3 sum)
{
  float len = sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
  return len > 0.0 ? sum / len : vec3(0.0, 0.0, 1.0);
}

// ---- Counter-based random numbers (Core/Base/CounterHash.h) ----------------------
uint bpHash(uint seed, uint element, uint generation, uint draw)
{
  uvec4 v = uvec4(seed, element, generation, draw) * BP_HASH_MULTIPLIER + BP_HASH_INCREMENT;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v.x;
}

uniform uint bpSeed;

float bpDraw(int e, float generation, uint draw)
{
  uint h = bpHash(bpSeed, uint(e), uint(generation), draw);
  return float(h >> 8u) * BP_HASH_UNIT;
}

// ---- Lifetime (lifetimeDraw in Core/Engine/Engine.h) ------------------------------
uniform float bpLifetimeMin;
uniform float bpLifetimeMax;
// A super set (Core/Elements/SuperSet.h) is released as one: every element draws as
// element 0 does.
uniform bool bpLinked;
// Release Pattern = Lattice (Core/Release/ReleaseLattice.h): a generation's lifetime
// is element 0's.
uniform bool bpLattice;

int bpDrawElement(int e)
{
  return bpLinked ? 0 : e;
}

float bpLifetimeOf(int e, float generation)
{
  return bpLifetimeMin +
    bpDraw(bpLattice ? 0 : bpDrawElement(e), generation, BP_LIFETIME_DRAW) *
      (bpLifetimeMax - bpLifetimeMin);
}
