// SPDX-License-Identifier: BSD-3-Clause
#include "GpuEngine.h"

#include "BoundParticlesShaders.h" // generated from Shaders/

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <sstream>

namespace bp
{
namespace
{
GLuint makeTexture2D(int width, int height, const float* data = nullptr)
{
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, data);
  return t;
}

/// Tightly packed uploads, leaving the caller's unpack state as it was (a
/// render window's context has its own).
class TightUnpack
{
public:
  TightUnpack()
  {
    for (int k = 0; k < 3; ++k)
    {
      glGetIntegerv(Names[k], &this->Saved[k]);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  }
  ~TightUnpack()
  {
    for (int k = 0; k < 3; ++k)
    {
      glPixelStorei(Names[k], this->Saved[k]);
    }
  }
  TightUnpack(const TightUnpack&) = delete;
  TightUnpack& operator=(const TightUnpack&) = delete;

private:
  static constexpr GLenum Names[3] = { GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH,
    GL_UNPACK_IMAGE_HEIGHT };
  GLint Saved[3] = { 4, 0, 0 };
};

/// A W x H texture of per-element values (element e at (e % W, e / W), so
/// row-major texel order is element order), 4 per element, zero padded.
GLuint makeElementTexture(int width, int height, const std::vector<float>& perElement)
{
  std::vector<float> padded(std::size_t(width) * height * 4, 0.0f);
  std::copy(perElement.begin(), perElement.end(), padded.begin());
  TightUnpack unpack;
  return makeTexture2D(width, height, padded.data());
}

/// The same with signed integers (RGBA32I), for element indices beyond 2^24.
GLuint makeElementIndexTexture(int width, int height, const std::vector<std::int32_t>& perElement)
{
  std::vector<std::int32_t> padded(std::size_t(width) * height * 4, -1);
  std::copy(perElement.begin(), perElement.end(), padded.begin());
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  TightUnpack unpack;
  glTexImage2D(
    GL_TEXTURE_2D, 0, GL_RGBA32I, width, height, 0, GL_RGBA_INTEGER, GL_INT, padded.data());
  return t;
}

/// Packs a list of RGBA texels into a texture `width` texels wide.
GLuint makeListTexture(const std::vector<float>& rgba, int width)
{
  const int count = std::max<int>(1, int(rgba.size() / 4));
  const int height = (count + width - 1) / width;
  std::vector<float> padded(std::size_t(width) * height * 4, 0.0f);
  std::copy(rgba.begin(), rgba.end(), padded.begin());
  return makeTexture2D(width, height, padded.data());
}

void setVec3Uniform(GLuint p, const char* name, const float* v)
{
  glUniform3f(glGetUniformLocation(p, name), v[0], v[1], v[2]);
}

std::string compile(GLenum type, const std::string& source, GLuint& shader)
{
  shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok)
  {
    return std::string();
  }
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, &log[0]);
  return log;
}
} // namespace

struct GpuEngine::Internals
{
  ElementTemplate Shape;
  Parameters Params;
  int E = 0, n = 0;
  int W = 0, H = 0;     // element grid
  int BlocksPerRow = 0; // bx
  int PW = 0, PH = 0;   // particle texture
  int SpringsWidth = 2, TrianglesWidth = 1;
  int SizeLimit = 1 << 30;
  bool GeneratedSprings = false;
  std::array<float, 4> FrameQuaternion = { 0, 0, 0, 1 };

  /// The advect pass: positions before the step (placed anew where reset) and
  /// after advection from t by h, or only the placed ones.
  void advect(bool placeOnly, double t, double h)
  {
    this->use(this->Advect);
    this->bind(this->Advect, "bpState", this->State[this->S]);
    this->bind(this->Advect, "bpElementState", this->ElementState[this->Cur]);
    this->bind(this->Advect, "bpRest", this->Rest);
    this->bind(this->Advect, "bpParticleInfo", this->ParticleInfo);
    setInt(this->Advect, "bpPlaceOnly", placeOnly ? 1 : 0);
    setInt(this->Advect, "bpIntegrator", int(this->Params.integrator));
    setFloat(this->Advect, "bpStep", float(h));
    if (this->Field)
    {
      const float weights[3] = { this->Field->timeWeight(t), this->Field->timeWeight(t + 0.5 * h),
        this->Field->timeWeight(t + h) };
      setVec3(this->Advect, "bpWeights", weights);
    }
    this->run({ this->Advected, this->Before }, this->PW, this->PH);
  }

  /// The reset pass: places flagged (or, initialising, all) elements.
  void reset(bool initialize)
  {
    this->use(this->Reset);
    this->bind(this->Reset, "bpElementState", this->ElementState[this->Cur]);
    this->bind(this->Reset, "bpCenters", this->Centers[this->C]);
    this->bind(this->Reset, "bpOrientations", this->Orientations[this->O]);
    setInt(this->Reset, "bpInitialize", initialize ? 1 : 0);
    glUniform4fv(
      glGetUniformLocation(this->Reset, "bpFrameQuaternion"), 1, this->FrameQuaternion.data());
    this->run({ this->ElementState[1 - this->Cur], this->Centers[1 - this->C],
                this->Orientations[1 - this->O] },
      this->W, this->H);
    this->Cur = 1 - this->Cur;
    this->C = 1 - this->C;
    this->O = 1 - this->O;
  }

  GLuint Vao = 0, Fbo = 0, CopyFbo = 0;
  GLuint Samples = 0, Saved[4] = { 0, 0, 0, 0 };
  GLuint SamplesProgram = 0;
  GLuint GaussSeidel = 0, ColouredSprings = 0;
  int Colours = 0;
  GLuint Reset = 0, Advect = 0, Restore = 0, Match = 0, MatchApply = 0, Test = 0, Finalize = 0,
         Normals = 0, Link = 0;
  GLuint MatchLinear[2] = { 0, 0 }; // the linear mode's goal matrix, packed (bp_match.frag)
  std::array<float, 9> RestMomentInverse = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  // A super set: per element its lattice site, its neighbours and link rest lengths.
  bool Linked = false;
  GLuint LatticeSites = 0, LinkNeighbours = 0, LinkRest = 0;
  GLuint ElementState[2] = { 0, 0 }, Centers[2] = { 0, 0 };
  int C = 0;   // current centres: only the reset pass writes them, so they flip apart
  int Cur = 0; // current element textures
  GLuint Orientations[2] = { 0, 0 }, MatchCenters = 0;
  int O = 0; // current orientation texture
  GLuint State[2] = { 0, 0 };
  int S = 0; // current particle state texture
  GLuint Advected = 0, Before = 0, Restored[2] = { 0, 0 }, NormalsTex = 0;
  GLuint Rest = 0, ParticleInfo = 0, Springs = 0, Triangles = 0;

  /// A field time step resident on the GPU, or arriving a slab of z layers
  /// at a time (stageSlice). Held by the data itself, so a freed and reused
  /// address can never pass for a resident time step.
  struct FieldSlot
  {
    GLuint texture = 0;
    std::shared_ptr<const std::vector<float>> data;
    int layers = 0; // z layers uploaded so far
    std::uint64_t lastUse = 0;
  };
  // Two time steps in use and one arriving: at most three volumes resident.
  std::array<FieldSlot, 3> Slots;
  std::array<int, 3> SlotDims = { 0, 0, 0 };
  std::uint64_t UseClock = 0;
  int FieldSlots[2] = { -1, -1 }; // the current field's slices
  GLuint AxesTex = 0;             // rectilinear axes' tables and bin lookups (bp_common.glsl)
  std::array<std::vector<float>, 3> AxesTables;
  int Bins[3] = { 1, 1, 1 };
  float BinScale[3] = { 0, 0, 0 };
  const VectorField* Field = nullptr;
  std::unique_ptr<VectorField> FieldCopy;

  /// The slot holding `data`, else a slot to receive it other than the two
  /// kept ones: an empty one or the least recently used.
  FieldSlot& slotFor(const std::shared_ptr<const std::vector<float>>& data, int keepA, int keepB)
  {
    for (FieldSlot& slot : this->Slots)
    {
      if (slot.data == data)
      {
        return slot;
      }
    }
    FieldSlot* best = nullptr;
    for (int k = 0; k < int(this->Slots.size()); ++k)
    {
      FieldSlot& slot = this->Slots[k];
      if (k != keepA && k != keepB && (!best || slot.lastUse < best->lastUse))
      {
        best = &slot;
      }
    }
    best->data = data;
    best->layers = 0;
    return *best;
  }

  /// Uploads up to `count` more z layers of the slot's data.
  void uploadLayers(FieldSlot& slot, const GridGeometry& g, int count)
  {
    const int nz = std::max(g.dims[2], 1);
    if (!slot.texture)
    {
      glGenTextures(1, &slot.texture);
      glBindTexture(GL_TEXTURE_3D, slot.texture);
      glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexImage3D(
        GL_TEXTURE_3D, 0, GL_RGB32F, g.dims[0], g.dims[1], nz, 0, GL_RGB, GL_FLOAT, nullptr);
    }
    const int first = slot.layers, last = std::min(nz, slot.layers + std::max(count, 0));
    if (last <= first)
    {
      return;
    }
    glBindTexture(GL_TEXTURE_3D, slot.texture);
    TightUnpack unpack;
    const std::size_t layer = std::size_t(g.dims[0]) * g.dims[1] * 3;
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, first, g.dims[0], g.dims[1], last - first, GL_RGB,
      GL_FLOAT, slot.data->data() + layer * first);
    slot.layers = last;
  }

  /// Drops every resident time step when the grid's size changes.
  void fitSlots(const GridGeometry& g)
  {
    if (this->SlotDims == g.dims)
    {
      return;
    }
    for (FieldSlot& slot : this->Slots)
    {
      if (slot.texture)
      {
        glDeleteTextures(1, &slot.texture);
      }
      slot = FieldSlot();
    }
    this->FieldSlots[0] = this->FieldSlots[1] = -1;
    this->SlotDims = g.dims;
  }

  /// Uploads the rectilinear axes' tables and bin lookups (bp_common.glsl)
  /// when they change. Empty on success, otherwise why the GPU cannot sample
  /// these axes.
  std::string uploadAxes(const VectorField& field)
  {
    std::array<std::vector<float>, 3> tables = { field.axisTable(0), field.axisTable(1),
      field.axisTable(2) };
    if (tables == this->AxesTables && this->AxesTex)
    {
      return std::string();
    }
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    std::array<std::vector<float>, 3> bins;
    std::size_t width = 1;
    for (int a = 0; a < 3; ++a)
    {
      const std::vector<float>& t = tables[a];
      this->Bins[a] = 1;
      this->BinScale[a] = 0.0f;
      if (t.empty())
      {
        continue;
      }
      const std::size_t points = t.size() / 2;
      double narrowest = HUGE_VAL;
      for (std::size_t i = 0; i + 1 < points; ++i)
      {
        narrowest = std::min(narrowest, double(t[2 * i + 2]) - double(t[2 * i]));
      }
      const double span = double(t[2 * (points - 1)]) - double(t[0]);
      const double count = std::ceil(2.0 * span / narrowest) + 1.0;
      if (!(narrowest > 0.0) || count > double(maxSize))
      {
        std::ostringstream err;
        err << "the field's cells along axis "
            << "XYZ"[a] << " range from " << narrowest << " to more than " << span / points
            << " in width; the GPU's lookup for them would need " << count
            << " texels, beyond its limit of " << maxSize << ". Use the CPU engine";
        return err.str();
      }
      this->Bins[a] = int(count);
      this->BinScale[a] = float(count / span);
      bins[a].resize(std::size_t(count));
      std::size_t cell = 0;
      for (std::size_t b = 0; b < bins[a].size(); ++b)
      {
        const float start = t[0] + float(double(b) * span / count);
        while (cell + 2 < points && t[2 * (cell + 1)] <= start)
        {
          ++cell;
        }
        bins[a][b] = float(cell);
      }
      width = std::max({ width, points, bins[a].size() });
    }
    this->AxesTables = tables;
    std::vector<float> texels(width * 6 * 2, 0.0f);
    for (int a = 0; a < 3; ++a)
    {
      std::copy(tables[a].begin(), tables[a].end(), texels.begin() + std::ptrdiff_t(a * width * 2));
      for (std::size_t b = 0; b < bins[a].size(); ++b)
      {
        texels[((3 + a) * width + b) * 2] = bins[a][b];
      }
    }
    if (!this->AxesTex)
    {
      glGenTextures(1, &this->AxesTex);
    }
    glBindTexture(GL_TEXTURE_2D, this->AxesTex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    TightUnpack unpack;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, GLsizei(width), 6, 0, GL_RG, GL_FLOAT, texels.data());
    return std::string();
  }

  std::string program(const std::string& fragment, GLuint& out)
  {
    const std::string header = "#version 330 core\n";
    GLuint vs = 0, fs = 0;
    std::string error = compile(GL_VERTEX_SHADER, header + bpShaderFullscreenVert, vs);
    if (error.empty())
    {
      error = compile(GL_FRAGMENT_SHADER, header + bpShaderCommon + fragment, fs);
    }
    if (!error.empty())
    {
      glDeleteShader(vs);
      glDeleteShader(fs);
      return "a GPU engine shader does not compile: " + error;
    }
    out = glCreateProgram();
    glAttachShader(out, vs);
    glAttachShader(out, fs);
    glLinkProgram(out);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(out, GL_LINK_STATUS, &ok);
    if (!ok)
    {
      char log[2048] = { 0 };
      glGetProgramInfoLog(out, sizeof(log) - 1, nullptr, log);
      return std::string("a GPU engine program does not link: ") + log;
    }
    return std::string();
  }

  // Uniforms are looked up by name: a pass ignores those it does not use.
  static void setInt(GLuint p, const char* name, int v)
  {
    glUniform1i(glGetUniformLocation(p, name), v);
  }
  static void setFloat(GLuint p, const char* name, float v)
  {
    glUniform1f(glGetUniformLocation(p, name), v);
  }
  static void setVec3(GLuint p, const char* name, const float* v)
  {
    glUniform3f(glGetUniformLocation(p, name), v[0], v[1], v[2]);
  }

  int Unit = 0;
  void bind(GLuint p, const char* name, GLuint texture, GLenum target = GL_TEXTURE_2D)
  {
    glActiveTexture(GLenum(GL_TEXTURE0 + this->Unit));
    glBindTexture(target, texture);
    setInt(p, name, this->Unit);
    ++this->Unit;
  }

  /// Uses program p with the uniforms every pass shares.
  void use(GLuint p)
  {
    glUseProgram(p);
    this->Unit = 0;
    const int grid[2] = { this->W, this->H };
    glUniform2i(glGetUniformLocation(p, "bpElementGrid"), grid[0], grid[1]);
    setInt(p, "bpBlocksPerRow", this->BlocksPerRow);
    setInt(p, "bpElements", this->E);
    setInt(p, "bpParticles", this->n);
    glUniform1ui(glGetUniformLocation(p, "bpSeed"), this->Params.seed);
    setVec3(p, "bpEmitterMin", this->Params.emitterMin.data());
    setVec3(p, "bpEmitterMax", this->Params.emitterMax.data());
    setFloat(p, "bpElementSize", this->Params.elementSize);
    setInt(p, "bpRandomOrientation", this->Params.randomOrientation ? 1 : 0);
    setVec3(p, "bpFrameRow0", this->Params.frame.data());
    setVec3(p, "bpFrameRow1", this->Params.frame.data() + 3);
    setVec3(p, "bpFrameRow2", this->Params.frame.data() + 6);
    setFloat(p, "bpLifetimeMin", this->Params.lifetimeMin);
    setFloat(p, "bpLifetimeMax", this->Params.lifetimeMax);
    setInt(p, "bpLinked", this->Linked ? 1 : 0);
    // Bound even when unused: an unbound sampler would share unit 0 with
    // samplers of other types, and GL refuses to draw.
    this->bind(p, "bpLatticeSites", this->LatticeSites);
    if (this->Field)
    {
      const VectorField::SamplingConstants c = this->Field->samplingConstants();
      setVec3(p, "bpOrigin", c.origin);
      setVec3(p, "bpInverseSpacing", c.inverseSpacing);
      setVec3(p, "bpMaxIndex", c.maxIndex);
      setVec3(p, "bpLower", c.lower);
      setVec3(p, "bpUpper", c.upper);
      glUniform3i(glGetUniformLocation(p, "bpNextCorner"), c.degenerate[0] ? 0 : 1,
        c.degenerate[1] ? 0 : 1, c.degenerate[2] ? 0 : 1);
      glUniform3i(
        glGetUniformLocation(p, "bpDegenerate"), c.degenerate[0], c.degenerate[1], c.degenerate[2]);
      glUniform3i(glGetUniformLocation(p, "bpRectilinear"), c.rectilinear[0], c.rectilinear[1],
        c.rectilinear[2]);
      const auto& dims = this->Field->grid().dims;
      glUniform3i(glGetUniformLocation(p, "bpLastCell"), std::max(dims[0] - 2, 0),
        std::max(dims[1] - 2, 0), std::max(dims[2] - 2, 0));
      glUniform3i(glGetUniformLocation(p, "bpBins"), this->Bins[0], this->Bins[1], this->Bins[2]);
      setVec3(p, "bpBinScale", this->BinScale);
      setInt(p, "bpUnsteady", this->Field->isSteady() ? 0 : 1);
      const int second = this->Field->isSteady() ? 0 : 1;
      this->bind(p, "bpField0", this->Slots[this->FieldSlots[0]].texture, GL_TEXTURE_3D);
      this->bind(p, "bpField1", this->Slots[this->FieldSlots[second]].texture, GL_TEXTURE_3D);
      this->bind(p, "bpAxes", this->AxesTex);
    }
  }

  /// Draws the full-screen triangle into the given targets.
  void run(std::initializer_list<GLuint> targets, int width, int height)
  {
    glBindFramebuffer(GL_FRAMEBUFFER, this->Fbo);
    GLenum buffers[4];
    int k = 0;
    for (GLuint t : targets)
    {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D, t, 0);
      buffers[k] = GLenum(GL_COLOR_ATTACHMENT0 + k);
      ++k;
    }
    for (int j = k; j < 4; ++j)
    {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + j), GL_TEXTURE_2D, 0, 0);
    }
    glDrawBuffers(k, buffers);
    glViewport(0, 0, width, height);
    // A render window's state may be anything: the passes need none of it.
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindVertexArray(this->Vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  void readTexture(GLuint texture, int width, int height, std::vector<float>& out) const
  {
    glBindFramebuffer(GL_FRAMEBUFFER, this->Fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    for (int j = 1; j < 4; ++j)
    {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + j), GL_TEXTURE_2D, 0, 0);
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    out.resize(std::size_t(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out.data());
  }

  /// Copies a texture's texels into another of the same size (a blit: GL 3.3).
  void copyTexture(GLuint from, GLuint to, int width, int height) const
  {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, this->Fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, from, 0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->CopyFbo);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, to, 0);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glDisable(GL_SCISSOR_TEST);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }

  /// A particle texture in the CPU engine's element-major order: xyz into
  /// `xyz` (3 per particle) and w into `w` (null to skip either).
  void readParticles(GLuint texture, std::vector<float>* xyz, std::vector<float>* w) const
  {
    std::vector<float> texels;
    this->readTexture(texture, this->PW, this->PH, texels);
    const std::size_t count = std::size_t(this->E) * this->n;
    if (xyz)
      xyz->resize(3 * count);
    if (w)
      w->resize(count);
    for (int e = 0; e < this->E; ++e)
      for (int i = 0; i < this->n; ++i)
      {
        const float* t = &texels[4 * this->particleTexel(e, i)];
        const std::size_t id = std::size_t(e) * this->n + i;
        if (xyz)
          std::copy(t, t + 3, xyz->begin() + 3 * id);
        if (w)
          (*w)[id] = t[3];
      }
  }

  std::size_t particleTexel(int e, int i) const
  {
    const int bx = i % this->BlocksPerRow, by = i / this->BlocksPerRow;
    const int x = bx * this->W + e % this->W, y = by * this->H + e / this->W;
    return std::size_t(y) * this->PW + x;
  }

  void deleteAll()
  {
    GLuint textures[] = { this->ElementState[0], this->ElementState[1], this->Centers[0],
      this->Centers[1], this->State[0], this->State[1], this->Advected, this->Before,
      this->Restored[0], this->Restored[1], this->NormalsTex, this->Rest, this->ParticleInfo,
      this->Springs, this->Triangles, this->Slots[0].texture, this->Slots[1].texture,
      this->Slots[2].texture, this->AxesTex, this->Orientations[0], this->Orientations[1],
      this->MatchCenters, this->ColouredSprings, this->Samples, this->Saved[0], this->Saved[1],
      this->Saved[2], this->Saved[3], this->MatchLinear[0], this->MatchLinear[1],
      this->LatticeSites, this->LinkNeighbours, this->LinkRest };
    for (GLuint t : textures)
    {
      if (t)
      {
        glDeleteTextures(1, &t);
      }
    }
    for (GLuint p :
      { this->Reset, this->Advect, this->Restore, this->Match, this->MatchApply, this->GaussSeidel,
        this->Test, this->Finalize, this->Normals, this->SamplesProgram, this->Link })
    {
      if (p)
      {
        glDeleteProgram(p);
      }
    }
    for (GLuint f : { this->Fbo, this->CopyFbo })
    {
      if (f)
      {
        glDeleteFramebuffers(1, &f);
      }
    }
    if (this->Vao)
    {
      glDeleteVertexArrays(1, &this->Vao);
    }
    *this = Internals();
  }

  Internals() = default;
  Internals& operator=(Internals&&) = default;
};

GpuEngine::GpuEngine()
  : I(new Internals)
{
}

GpuEngine::~GpuEngine() = default;

int GpuEngine::particleTextureWidth() const
{
  return this->I->PW;
}

int GpuEngine::particleTextureHeight() const
{
  return this->I->PH;
}

void GpuEngine::release()
{
  const int limit = this->I->SizeLimit;
  const bool generated = this->I->GeneratedSprings;
  this->I->deleteAll();
  this->I->SizeLimit = limit;
  this->I->GeneratedSprings = generated;
}

void GpuEngine::setGeneratedSprings(bool generated)
{
  this->I->GeneratedSprings = generated;
}

bool GpuEngine::generatedSprings() const
{
  return this->I->GeneratedSprings;
}

void GpuEngine::setTextureSizeLimit(int texels)
{
  this->I->SizeLimit = texels;
}

std::string GpuEngine::configure(const ElementTemplate& shape, const Parameters& p)
{
  // The same checks as the CPU engine, then the GPU's own limits.
  const std::string error = Engine::validate(shape, p);
  if (!error.empty())
  {
    return error;
  }
  const std::array<float, 4> frameQuaternion = quaternionFromRotation(p.frame);
  this->release();
  Internals& S = *this->I;
  S.Shape = shape;
  S.Params = p;
  S.E = int(p.numberOfElements);
  S.n = int(shape.particleCount());
  const ParticleLayout layout = ParticleLayout::of(p.numberOfElements, shape.particleCount());
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  maxSize = std::min<GLint>(maxSize, S.SizeLimit);
  if (layout.width > maxSize || layout.height > maxSize)
  {
    std::ostringstream err;
    err << p.numberOfElements << " elements of " << S.n << " particles need a " << layout.width
        << " x " << layout.height << " state texture, beyond this GPU's GL_MAX_TEXTURE_SIZE of "
        << maxSize;
    this->release();
    return err.str();
  }
  S.W = int(layout.elementGrid[0]);
  S.H = int(layout.elementGrid[1]);
  S.BlocksPerRow = int(layout.blocksPerRow);
  S.PW = int(layout.width);
  S.PH = int(layout.height);

  for (auto pass :
    { std::make_pair(bpShaderResetFrag, &S.Reset), std::make_pair(bpShaderAdvectFrag, &S.Advect),
      std::make_pair(bpShaderRestoreFrag, &S.Restore), std::make_pair(bpShaderMatchFrag, &S.Match),
      std::make_pair(bpShaderMatchApplyFrag, &S.MatchApply),
      std::make_pair(bpShaderGaussSeidelFrag, &S.GaussSeidel),
      std::make_pair(bpShaderTestFrag, &S.Test), std::make_pair(bpShaderFinalizeFrag, &S.Finalize),
      std::make_pair(bpShaderNormalsFrag, &S.Normals),
      std::make_pair(bpShaderSamplesFrag, &S.SamplesProgram),
      std::make_pair(bpShaderLinkFrag, &S.Link) })
  {
    const std::string programError = S.program(pass.first, *pass.second);
    if (!programError.empty())
    {
      this->release();
      return programError;
    }
  }
  glGenVertexArrays(1, &S.Vao);
  glGenFramebuffers(1, &S.Fbo);
  glGenFramebuffers(1, &S.CopyFbo);
  for (int k = 0; k < 2; ++k)
  {
    S.ElementState[k] = makeTexture2D(S.W, S.H);
    S.Centers[k] = makeTexture2D(S.W, S.H);
    S.Orientations[k] = makeTexture2D(S.W, S.H);
    S.State[k] = makeTexture2D(S.PW, S.PH);
    S.Restored[k] = makeTexture2D(S.PW, S.PH);
  }
  S.MatchCenters = makeTexture2D(S.W, S.H);
  S.MatchLinear[0] = makeTexture2D(S.W, S.H);
  S.MatchLinear[1] = makeTexture2D(S.W, S.H);
  S.RestMomentInverse = restMomentInverse(shape, p.elementSize);
  // The super set's lattice, the same table the CPU engine builds.
  const LinkTable links =
    makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax);
  S.Linked = !links.empty();
  std::vector<float> sites(S.Linked ? 4 * std::size_t(S.E) : 0, 0.0f);
  for (std::size_t e = 0; e < sites.size() / 4; ++e)
  {
    std::copy_n(&links.sites[3 * e], 3, &sites[4 * e]);
  }
  S.LatticeSites = makeElementTexture(S.W, S.H, sites);
  if (S.Linked)
  {
    S.LinkRest = makeElementTexture(S.W, S.H, links.rest);
    S.LinkNeighbours = makeElementIndexTexture(S.W, S.H, links.neighbours);
  }
  S.FrameQuaternion = frameQuaternion;
  S.Advected = makeTexture2D(S.PW, S.PH);
  S.Before = makeTexture2D(S.PW, S.PH);
  S.NormalsTex = makeTexture2D(S.PW, S.PH);
  S.Samples = makeTexture2D(S.PW, S.PH);

  // The template: rest positions, per-particle spring and triangle lists in
  // index order (so sums run in the CPU engine's order), spring parameters.
  std::vector<float> rest, info(std::size_t(S.n) * 2 * 4, 0.0f), springs, triangles;
  std::vector<int> degree(S.n, 0);
  std::vector<std::uint8_t> pinned(S.n, 0);
  if (!shape.pinned.empty())
  {
    pinned = shape.pinned;
  }
  for (const Spring& s : shape.springs)
  {
    ++degree[s.a];
    ++degree[s.b];
  }
  for (int i = 0; i < S.n; ++i)
  {
    rest.insert(rest.end(), { shape.rest[i][0], shape.rest[i][1], shape.rest[i][2], 0.0f });
    float* row0 = &info[4 * i];
    row0[0] = float(springs.size() / 8);
    for (const Spring& s : shape.springs)
    {
      if (s.a != std::uint32_t(i) && s.b != std::uint32_t(i))
      {
        continue;
      }
      const bool pa = pinned[s.a] != 0, pb = pinned[s.b] != 0;
      const float shareA = pa ? 0.0f : (pb ? 1.0f : 0.5f);
      const float shareB = pb ? 0.0f : (pa ? 1.0f : 0.5f);
      const float share = s.a == std::uint32_t(i) ? shareA : -shareB;
      springs.insert(springs.end(),
        { float(s.a), float(s.b), share, 0.0f, s.restLength * p.elementSize, s.stiffness, 0.0f,
          0.0f });
    }
    row0[1] = float(springs.size() / 8) - row0[0];
    row0[2] = degree[i] > 0 ? 1.0f / float(degree[i]) : 0.0f;
    row0[3] = pinned[i] ? 1.0f : 0.0f;
    float* row1 = &info[4 * (S.n + i)];
    row1[0] = float(triangles.size() / 4);
    for (const auto& t : shape.triangles)
    {
      if (t[0] == std::uint32_t(i) || t[1] == std::uint32_t(i) || t[2] == std::uint32_t(i))
      {
        triangles.insert(triangles.end(), { float(t[0]), float(t[1]), float(t[2]), 0.0f });
      }
    }
    row1[1] = float(triangles.size() / 4) - row1[0];
  }
  // The Jacobi pass with the springs as code (thesis §3.5) instead of a
  // buffer: same corrections in the same order, so the same bits.
  if (S.GeneratedSprings)
  {
    std::ostringstream code;
    code << "vec3 bpSpringSum(int e, int i, vec4 info)\n{\n  vec3 acc = vec3(0.0);\n"
         << "  switch (i)\n  {\n";
    code.precision(9);
    code << std::scientific;
    for (int i = 0; i < S.n; ++i)
    {
      const int first = int(info[4 * i]), count = int(info[4 * i + 1]);
      if (count == 0)
        continue;
      code << "    case " << i << ":\n";
      for (int k = first; k < first + count; ++k)
      {
        const float* e = &springs[8 * std::size_t(k)];
        code << "      acc += bpSpringCorrection(e, " << int(e[0]) << ", " << int(e[1]) << ", "
             << e[2] << ", " << e[4] << ", " << e[5] << ");\n";
      }
      code << "      break;\n";
    }
    code << "  }\n  return acc;\n}\n";
    std::string fragment = std::string("#define BP_GENERATED_SPRINGS\n") + bpShaderRestoreFrag;
    const std::string tag = "//BP::GeneratedSprings";
    fragment.replace(fragment.find(tag), tag.size(), code.str());
    glDeleteProgram(S.Restore);
    S.Restore = 0;
    const std::string programError = S.program(fragment, S.Restore);
    if (!programError.empty())
    {
      this->release();
      return programError;
    }
  }

  // Gauss-Seidel: per (particle, colour) the particle's spring of that colour.
  const std::vector<int> colour = colourSprings(std::size_t(S.n), shape.springs);
  S.Colours = colour.empty() ? 0 : *std::max_element(colour.begin(), colour.end()) + 1;
  std::vector<float> coloured(std::size_t(2 * S.n) * std::max(S.Colours, 1) * 4, 0.0f);
  for (std::size_t k = 0; k < shape.springs.size(); ++k)
  {
    const Spring& s = shape.springs[k];
    const bool pa = pinned[s.a] != 0, pb = pinned[s.b] != 0;
    const float shares[2] = { pa ? 0.0f : (pb ? 1.0f : 0.5f), pb ? 0.0f : (pa ? 1.0f : 0.5f) };
    const std::uint32_t ends[2] = { s.a, s.b };
    for (int side = 0; side < 2; ++side)
    {
      float* texel = &coloured[4 * (std::size_t(colour[k]) * 2 * S.n + 2 * ends[side])];
      const float entry[8] = { float(s.a), float(s.b), side == 0 ? shares[0] : -shares[1], 1.0f,
        s.restLength * p.elementSize, s.stiffness, 0.0f, 0.0f };
      std::copy(entry, entry + 8, texel);
    }
  }
  S.ColouredSprings = makeTexture2D(2 * S.n, std::max(S.Colours, 1), coloured.data());
  S.Rest = makeTexture2D(S.n, 1, rest.data());
  S.ParticleInfo = makeTexture2D(S.n, 2, info.data());
  S.SpringsWidth = int(std::min<std::size_t>(std::max<std::size_t>(springs.size() / 4, 2), 4096));
  S.SpringsWidth += S.SpringsWidth % 2;
  S.Springs = makeListTexture(springs, S.SpringsWidth);
  S.TrianglesWidth =
    int(std::min<std::size_t>(std::max<std::size_t>(triangles.size() / 4, 1), 4096));
  S.Triangles = makeListTexture(triangles, S.TrianglesWidth);
  if (glGetError() != GL_NO_ERROR)
  {
    this->release();
    return "the GPU could not create the engine's float textures (RGBA32F render targets)";
  }
  return std::string();
}

std::string GpuEngine::setField(const VectorField& field)
{
  Internals& S = *this->I;
  const GridGeometry& g = field.grid();
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  for (int a = 0; a < 3; ++a)
  {
    if (g.dims[a] > max3D)
    {
      std::ostringstream err;
      err << "the field's " << g.dims[a] << " points along axis "
          << "XYZ"[a] << " exceed this GPU's GL_MAX_3D_TEXTURE_SIZE of " << max3D;
      return err.str();
    }
  }
  const std::string axesError = S.uploadAxes(field);
  if (!axesError.empty())
  {
    return axesError;
  }
  S.FieldCopy.reset(new VectorField(field));
  S.Field = S.FieldCopy.get();
  S.fitSlots(g);
  const FieldSlice* slices[2] = { &field.firstSlice(), &field.secondSlice() };
  int chosen[2] = { -1, -1 };
  for (int k = 0; k < 2; ++k)
  {
    if (!slices[k]->velocity)
    {
      continue;
    }
    // The first slice's slot stays out of reach of the second's eviction.
    Internals::FieldSlot& slot = S.slotFor(slices[k]->velocity, chosen[0], -1);
    // Whatever has not arrived by slabs arrives now, at once.
    S.uploadLayers(slot, g, std::max(g.dims[2], 1));
    slot.lastUse = ++S.UseClock;
    chosen[k] = int(&slot - S.Slots.data());
  }
  S.FieldSlots[0] = chosen[0];
  S.FieldSlots[1] = chosen[1];
  return glGetError() == GL_NO_ERROR ? std::string()
                                     : std::string("the GPU could not hold the field's time steps");
}

int GpuEngine::stageSlice(const FieldSlice& slice, std::size_t maxBytes)
{
  Internals& S = *this->I;
  if (!S.Field || !slice.velocity || slice.velocity->size() != 3 * S.Field->grid().pointCount())
  {
    return 0;
  }
  const GridGeometry& g = S.Field->grid();
  Internals::FieldSlot& slot = S.slotFor(slice.velocity, S.FieldSlots[0], S.FieldSlots[1]);
  const std::size_t layerBytes = std::size_t(g.dims[0]) * g.dims[1] * 3 * sizeof(float);
  S.uploadLayers(slot, g, int(std::max<std::size_t>(1, maxBytes / layerBytes)));
  return std::max(g.dims[2], 1) - slot.layers;
}

int GpuEngine::stageSliceWithin(const FieldSlice& slice, double seconds)
{
  const auto start = std::chrono::steady_clock::now();
  int remaining;
  do
  {
    remaining = this->stageSlice(slice, std::size_t(1) << 20);
  } while (remaining > 0 &&
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds);
  return remaining;
}

int GpuEngine::residentTimeSteps() const
{
  int count = 0;
  for (const auto& slot : this->I->Slots)
  {
    count += slot.data ? 1 : 0;
  }
  return count;
}

void GpuEngine::initialize()
{
  Internals& S = *this->I;
  // Place every element as generation 0 ...
  S.reset(true);
  S.advect(true, 0.0, 0.0);
  // ... with no flag set and zero force, as Engine::initialize leaves them.
  S.use(S.Test);
  S.bind(S.Test, "bpElementState", S.ElementState[S.Cur]);
  S.bind(S.Test, "bpPositions", S.Advected);
  Internals::setInt(S.Test, "bpSettleOnly", 1);
  S.run({ S.ElementState[1 - S.Cur] }, S.W, S.H);
  S.Cur = 1 - S.Cur;
  S.use(S.Finalize);
  S.bind(S.Finalize, "bpRestored", S.Advected);
  S.bind(S.Finalize, "bpAdvected", S.Advected);
  S.bind(S.Finalize, "bpBefore", S.Before);
  S.bind(S.Finalize, "bpElementState", S.ElementState[S.Cur]);
  S.run({ S.State[1 - S.S] }, S.PW, S.PH);
  S.S = 1 - S.S;
  this->updateNormals();
}

void GpuEngine::step(double t, double h)
{
  Internals& S = *this->I;
  const Parameters& P = S.Params;
  // 1. Reset.
  S.reset(false);
  // 2. Advect.
  S.advect(false, t, h);
  // 3. Restore: K iterations of the elements' own restoration, each followed,
  // in a super set, by one pass over the links (Engine::stepLinked).
  GLuint positions = S.Advected;
  int pass = 0; // passes write Restored[0] and [1] in turn, never the one they read
  const bool springs = !S.Shape.springs.empty();
  for (int k = 0; k < P.iterations; ++k)
  {
    if (P.restoration == Restoration::ShapeMatching)
    {
      // A fit per element, then a move per particle.
      S.use(S.Match);
      S.bind(S.Match, "bpPositions", positions);
      S.bind(S.Match, "bpRest", S.Rest);
      S.bind(S.Match, "bpOrientations", S.Orientations[S.O]);
      Internals::setInt(S.Match, "bpLinearMatching", P.linearShapeMatching ? 1 : 0);
      Internals::setFloat(S.Match, "bpLinearBlend", P.linearBlend);
      setVec3Uniform(S.Match, "bpRestMomentInverse0", S.RestMomentInverse.data());
      setVec3Uniform(S.Match, "bpRestMomentInverse1", S.RestMomentInverse.data() + 3);
      setVec3Uniform(S.Match, "bpRestMomentInverse2", S.RestMomentInverse.data() + 6);
      S.run(
        { S.MatchCenters, S.Orientations[1 - S.O], S.MatchLinear[0], S.MatchLinear[1] }, S.W, S.H);
      S.O = 1 - S.O;
      S.use(S.MatchApply);
      S.bind(S.MatchApply, "bpPositions", positions);
      S.bind(S.MatchApply, "bpRest", S.Rest);
      S.bind(S.MatchApply, "bpParticleInfo", S.ParticleInfo);
      S.bind(S.MatchApply, "bpMatchCenters", S.MatchCenters);
      S.bind(S.MatchApply, "bpOrientations", S.Orientations[S.O]);
      S.bind(S.MatchApply, "bpMatchLinear0", S.MatchLinear[0]);
      S.bind(S.MatchApply, "bpMatchLinear1", S.MatchLinear[1]);
      Internals::setInt(S.MatchApply, "bpLinearMatching", P.linearShapeMatching ? 1 : 0);
      Internals::setFloat(S.MatchApply, "bpShapeStiffness", P.shapeStiffness);
      S.run({ S.Restored[pass % 2] }, S.PW, S.PH);
      positions = S.Restored[pass++ % 2];
    }
    else if (P.restoration == Restoration::GaussSeidel && springs)
    {
      // A pass per colour of springs.
      for (int c = 0; c < S.Colours; ++c)
      {
        S.use(S.GaussSeidel);
        S.bind(S.GaussSeidel, "bpPositions", positions);
        S.bind(S.GaussSeidel, "bpColouredSprings", S.ColouredSprings);
        Internals::setInt(S.GaussSeidel, "bpColour", c);
        S.run({ S.Restored[pass % 2] }, S.PW, S.PH);
        positions = S.Restored[pass++ % 2];
      }
    }
    else if (springs)
    {
      S.use(S.Restore);
      S.bind(S.Restore, "bpPositions", positions);
      S.bind(S.Restore, "bpParticleInfo", S.ParticleInfo);
      S.bind(S.Restore, "bpSprings", S.Springs);
      Internals::setInt(S.Restore, "bpSpringsWidth", S.SpringsWidth);
      Internals::setInt(
        S.Restore, "bpAveraged", P.restoration == Restoration::AveragedJacobi ? 1 : 0);
      Internals::setFloat(S.Restore, "bpRelaxation", P.relaxation);
      S.run({ S.Restored[pass % 2] }, S.PW, S.PH);
      positions = S.Restored[pass++ % 2];
    }
    if (S.Linked)
    {
      S.use(S.Link);
      S.bind(S.Link, "bpPositions", positions);
      S.bind(S.Link, "bpParticleInfo", S.ParticleInfo);
      S.bind(S.Link, "bpLinkNeighbours", S.LinkNeighbours);
      S.bind(S.Link, "bpLinkRest", S.LinkRest);
      Internals::setFloat(S.Link, "bpLinkStiffness", P.linkStiffness);
      S.run({ S.Restored[pass % 2] }, S.PW, S.PH);
      positions = S.Restored[pass++ % 2];
    }
  }
  // 5. Reposition test, then the new state.
  S.use(S.Test);
  S.bind(S.Test, "bpElementState", S.ElementState[S.Cur]);
  S.bind(S.Test, "bpPositions", positions);
  Internals::setInt(S.Test, "bpSettleOnly", 0);
  Internals::setInt(S.Test, "bpAnyParticle", P.resetWhen == ResetWhen::AnyParticleLeaves ? 1 : 0);
  Internals::setFloat(S.Test, "bpStep", float(h));
  S.run({ S.ElementState[1 - S.Cur] }, S.W, S.H);
  S.Cur = 1 - S.Cur;
  S.use(S.Finalize);
  S.bind(S.Finalize, "bpRestored", positions);
  S.bind(S.Finalize, "bpAdvected", S.Advected);
  S.bind(S.Finalize, "bpBefore", S.Before);
  S.bind(S.Finalize, "bpElementState", S.ElementState[S.Cur]);
  S.run({ S.State[1 - S.S] }, S.PW, S.PH);
  S.S = 1 - S.S;
}

void GpuEngine::updateNormals()
{
  Internals& S = *this->I;
  S.use(S.Normals);
  S.bind(S.Normals, "bpState", S.State[S.S]);
  S.bind(S.Normals, "bpParticleInfo", S.ParticleInfo);
  S.bind(S.Normals, "bpTriangles", S.Triangles);
  Internals::setInt(S.Normals, "bpTrianglesWidth", S.TrianglesWidth);
  S.run({ S.NormalsTex }, S.PW, S.PH);
}

void GpuEngine::saveState()
{
  Internals& S = *this->I;
  if (!S.Saved[0])
  {
    S.Saved[0] = makeTexture2D(S.PW, S.PH);
    for (int k = 1; k < 4; ++k)
    {
      S.Saved[k] = makeTexture2D(S.W, S.H);
    }
  }
  S.copyTexture(S.State[S.S], S.Saved[0], S.PW, S.PH);
  S.copyTexture(S.ElementState[S.Cur], S.Saved[1], S.W, S.H);
  S.copyTexture(S.Centers[S.C], S.Saved[2], S.W, S.H);
  S.copyTexture(S.Orientations[S.O], S.Saved[3], S.W, S.H);
}

void GpuEngine::restoreState()
{
  Internals& S = *this->I;
  if (!S.Saved[0])
  {
    return;
  }
  S.copyTexture(S.Saved[0], S.State[S.S], S.PW, S.PH);
  S.copyTexture(S.Saved[1], S.ElementState[S.Cur], S.W, S.H);
  S.copyTexture(S.Saved[2], S.Centers[S.C], S.W, S.H);
  S.copyTexture(S.Saved[3], S.Orientations[S.O], S.W, S.H);
}

void GpuEngine::updateFieldSamples(double t)
{
  Internals& S = *this->I;
  if (!S.Field)
  {
    return;
  }
  S.use(S.SamplesProgram);
  S.bind(S.SamplesProgram, "bpState", S.State[S.S]);
  Internals::setFloat(S.SamplesProgram, "bpSampleWeight", S.Field->timeWeight(t));
  const auto& spacing = S.Field->grid().spacing;
  const float h[3] = { float(spacing[0]), float(spacing[1]), float(spacing[2]) };
  setVec3Uniform(S.SamplesProgram, "bpSpacing", h);
  S.run({ S.Samples }, S.PW, S.PH);
}

void GpuEngine::readFieldSamples(std::vector<float>* velocity, std::vector<float>* vorticity) const
{
  this->I->readParticles(this->I->Samples, velocity, vorticity);
}

GpuEngine::DrawInputs GpuEngine::drawInputs() const
{
  const Internals& S = *this->I;
  DrawInputs d;
  d.positions = S.State[S.S];
  d.normals = S.NormalsTex;
  d.samples = S.Samples;
  d.elements = S.ElementState[S.Cur];
  d.centers = S.Centers[S.C];
  d.elementGrid[0] = S.W;
  d.elementGrid[1] = S.H;
  d.blocksPerRow = S.BlocksPerRow;
  d.elementCount = S.E;
  d.particlesPerElement = S.n;
  return d;
}

void GpuEngine::read(
  std::vector<float>* positions, std::vector<float>* forces, std::vector<float>* normals) const
{
  const Internals& S = *this->I;
  if (positions || forces)
  {
    S.readParticles(S.State[S.S], positions, forces);
  }
  if (normals)
  {
    S.readParticles(S.NormalsTex, normals, nullptr);
  }
}

void GpuEngine::readElements(std::vector<float>* lifetimes, std::vector<float>* generations,
  std::vector<float>* centers, std::vector<float>* orientations,
  std::vector<float>* resetFlags) const
{
  const Internals& S = *this->I;
  std::vector<float> texels;
  if (orientations)
  {
    S.readTexture(S.Orientations[S.O], S.W, S.H, texels);
    orientations->assign(texels.begin(), texels.begin() + 4 * std::size_t(S.E));
  }
  S.readTexture(S.ElementState[S.Cur], S.W, S.H, texels);
  if (lifetimes)
    lifetimes->resize(S.E);
  if (generations)
    generations->resize(S.E);
  if (resetFlags)
    resetFlags->resize(S.E);
  for (int e = 0; e < S.E; ++e)
  {
    if (lifetimes)
      (*lifetimes)[e] = texels[4 * e];
    if (generations)
      (*generations)[e] = texels[4 * e + 1];
    if (resetFlags)
      (*resetFlags)[e] = texels[4 * e + 2];
  }
  if (centers)
  {
    S.readTexture(S.Centers[S.C], S.W, S.H, texels);
    centers->resize(std::size_t(S.E) * 3);
    for (int e = 0; e < S.E; ++e)
      std::copy(&texels[4 * e], &texels[4 * e] + 3, centers->begin() + 3 * e);
  }
}

} // namespace bp
