// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DrawTables.h
 * @brief What the Bound Particles display's draw needs from a configuration,
 * made once per configuration: the template as polydata, the super set's
 * link pairs, the trails' corner table, and the integer textures that carry
 * the two tables to the draw shader.
 *
 * Nothing here changes while the engine steps; vtkOpenGLBoundParticleMapper
 * makes these when it runs a Configure call and uploads the tables on the
 * next draw.
 */
#ifndef BoundParticles_DrawTables_h
#define BoundParticles_DrawTables_h

#include "vtkNew.h"           // for vtkNew
#include "vtkSmartPointer.h"  // for vtkSmartPointer
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>

#include <cstddef>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkWindow;

namespace bp
{
struct ElementTemplate;
struct Parameters;
}

namespace bpvtk
{

/**
 * The template as VTK polydata: its triangles (or springs as lines, or the
 * lone particle as a vertex) over its points scaled by `size`, so VTK builds
 * one index buffer whose indices are template particle indices. With `links`,
 * a template without lines gets one stand-in line cell, so that VTK also
 * builds its line shader, which draws the super set's links; the cell itself
 * is never drawn.
 */
vtkSmartPointer<vtkPolyData> templatePolyData(
  const bp::ElementTemplate& shape, float size, bool links);

/// The links of the super set of `p` as pairs of element indices, in the
/// order of the CPU output's link cells (bp::forEachLink); empty unlinked.
std::vector<int> linkPairs(const bp::Parameters& p);

/**
 * For each template particle, the triangles it is a corner of, so the draw
 * shader can compute a trail pose's normals from the pose's positions as
 * bp::elementNormals does: row i holds the corners (in the triangle's own
 * order, so the normal's sign is the mesh's) of each triangle with i among
 * them, then (-1, -1, -1, -1) where the row ends early; 4 ints a texel.
 * `width` is the longest row (1 for a template without triangles: its rows
 * are all ends).
 */
std::vector<int> cornerTable(const bp::ElementTemplate& shape, int& width);

/**
 * A table of integer texels for the draw shader and its texture (RG32I for
 * 2 ints a texel, RGBA32I for 4): set once per configuration, uploaded by
 * the first draw after that, and again after the context lost it.
 */
class IntegerTable
{
public:
  /// `components`: ints a texel, 2 or 4.
  explicit IntegerTable(int components);
  ~IntegerTable();
  IntegerTable(const IntegerTable&) = delete;
  IntegerTable& operator=(const IntegerTable&) = delete;

  /// The next texels, in rows of `width` texels; width 0: as many a row as a
  /// texture row holds, the last row padded with zeros.
  void set(std::vector<int> texels, int width);
  bool empty() const { return this->Texels.empty(); }
  /// Texels set (and not given up by upload).
  std::size_t texelCount() const;
  /// Rows the table takes in a texture of at most `maxSize` texels a side.
  std::size_t rows(int maxSize) const;

  /// Uploads the table if it is not on the GPU yet; false, the table emptied,
  /// when it does not fit a texture of `maxSize` texels a side.
  bool upload(vtkOpenGLRenderWindow* window, int maxSize);
  /// Texels a row of the uploaded texture; 0 when there is none.
  int width() const;
  /// The uploaded texture; 0 when there is none.
  unsigned handle() const;
  void release(vtkWindow* window);

private:
  /// Texels a row in a texture of at most `maxSize` texels a side.
  int rowWidth(int maxSize) const;

  int Components;
  std::vector<int> Texels;
  int RowWidth = 0;      // as set: 0 wraps at the texture size
  int UploadedWidth = 0; // texels a row on the GPU
  bool Uploaded = false;
  vtkNew<vtkTextureObject> Texture;
};

} // namespace bpvtk

#endif
