/**
 * @class   vtkVoxelGIScenes
 * @brief   Scenes the project builds itself, for the demo, the examples and the tests.
 *
 * AddCornellBox() fills a renderer with a Cornell-style box: white floor, ceiling and back
 * wall, red left wall, green right wall, two white blocks, an emissive panel under the
 * ceiling and a positional light just below it; the camera looks in through the open front.
 * The box spans [0, 5.5] on each axis (world units).
 *
 * @sa vtkVoxelGIPass
 */
#ifndef vtkVoxelGIScenes_h
#define vtkVoxelGIScenes_h

#include "vtkObject.h"
#include "vtkRenderingVoxelGIModule.h" // for export macro

class vtkRenderer;

class VTKRENDERINGVOXELGI_EXPORT vtkVoxelGIScenes : public vtkObject
{
public:
  static vtkVoxelGIScenes* New();
  vtkTypeMacro(vtkVoxelGIScenes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Add the Cornell box's actors and light to `renderer` and aim its camera into the box.
   * The ceiling panel gets an emission of `panelEmission` (vtkVoxelGIPass::EMISSION).
   */
  static void AddCornellBox(vtkRenderer* renderer, double panelEmission = 4.0);

protected:
  vtkVoxelGIScenes() = default;
  ~vtkVoxelGIScenes() override = default;

private:
  vtkVoxelGIScenes(const vtkVoxelGIScenes&) = delete;
  void operator=(const vtkVoxelGIScenes&) = delete;
};

#endif
