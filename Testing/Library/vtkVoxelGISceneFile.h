/**
 * @class   vtkVoxelGISceneFile
 * @brief   Writes a renderer's scene as a description that VTK and Blender Cycles both read,
 *          and reads it back into a renderer.
 *
 * The error study compares the pass with a path-traced reference; this class lets it do so for
 * any scene a program builds, not only vtkVoxelGIScenes'. Write() turns the renderer's visible
 * actors, lights and camera into FILE.json (camera, lights, background, image size and, per
 * actor, VTK's material and the terms Cycles renders: diffuse, specular, emission; per
 * homogeneous volume, its box, matrix, colour and density) and FILE.obj
 * + FILE.mtl (world-space polygons, normals and scalar colours as vertex colours, one material
 * per actor). Testing/Reference/render_cycles.py renders the description with Cycles; Read()
 * rebuilds the same actors, lights and camera in a renderer, as VoxelGIErrorStudy does for a
 * scene file.
 *
 * Only what has the same meaning in both renderers is written. Write() refuses a scene that
 * uses anything else and names every such use in GetProblems(): translucent, textured, PBR,
 * unlit, wireframe or point props, lines and vertices, cell or field scalar colours, glyph and
 * composite mappers, volumes other than homogeneous ones (constant opacity and colour over
 * axis-aligned image data, unshaded, composite), image slices and other 3D props, spot lights,
 * attenuated lights other than inverse square, image-based lighting, gradient or textured backgrounds, parallel
 * projection, and ambient
 * terms other than the background's sky light (Ka Ca = background x diffuse colour). Camera
 * lights and headlights are written as the scene lights they are for the current camera,
 * marked so that Read() makes them follow the camera again, and overlays (2D actors) are left
 * out; GetNotes() says so.
 *
 * @sa vtkVoxelGIScenes vtkVoxelGIPass
 */
#ifndef vtkVoxelGISceneFile_h
#define vtkVoxelGISceneFile_h

#include "vtkObject.h"
#include "vtkTestingVoxelGIModule.h" // for export macro

#include <string> // for the problems and notes

class vtkRenderer;

class VTKTESTINGVOXELGI_EXPORT vtkVoxelGISceneFile : public vtkObject
{
public:
  static vtkVoxelGISceneFile* New();
  vtkTypeMacro(vtkVoxelGISceneFile, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The description's JSON file; the OBJ and MTL files lie beside it with the same stem.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  /**
   * Image size written into the description (the reference is rendered at it). 0 (default)
   * takes the renderer's size in pixels, or 200 x 200 when it has no window.
   */
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);

  /**
   * Write `renderer`'s scene. Returns false, writes nothing and reports one error listing
   * every problem when the scene cannot be described (non-finite coordinates, normals,
   * materials, lights, camera or background among them: they would not read back). Actors
   * without polygons are left out with a note. Returns false with one error, leaving no new
   * file, when the files cannot be written (a missing directory, a full device, a directory's
   * or an empty name).
   */
  bool Write(vtkRenderer* renderer);

  /**
   * Add the described actors and lights to `renderer`, set its camera and background, and
   * set Size to the description's image size. OBJ files from other writers read too
   * (relative indices, texture coordinates left out). Returns false with one error naming the
   * field or line, and leaves the renderer as it was, when the files are missing or damaged:
   * an index beyond the points, a token that is not a finite number, a JSON field missing or
   * of the wrong type.
   */
  bool Read(vtkRenderer* renderer);

  /**
   * What the last Write() could not describe, one per line (empty when it succeeded).
   */
  const char* GetProblems() { return this->Problems.c_str(); }

  /**
   * What the last Write() changed or left out on purpose, one per line.
   */
  const char* GetNotes() { return this->Notes.c_str(); }

protected:
  vtkVoxelGISceneFile() = default;
  ~vtkVoxelGISceneFile() override;

private:
  vtkVoxelGISceneFile(const vtkVoxelGISceneFile&) = delete;
  void operator=(const vtkVoxelGISceneFile&) = delete;

  char* FileName = nullptr;
  int Size[2] = { 0, 0 };
  std::string Problems;
  std::string Notes;
};

#endif
