/**
 * @class   vtkVoxelGIScenes
 * @brief   Scenes the project builds itself, for the demo, the examples and the tests.
 *
 * AddCornellBox() fills a renderer with a Cornell-style box: white floor, ceiling and back
 * wall, red left wall, green right wall, two white blocks, an emissive panel under the
 * ceiling and a positional light just below it; the camera looks in through the open front.
 * The box spans [0, 5.5] on each axis (world units).
 *
 * The other scenes are those of the error study against a path-traced reference:
 * AddGlossyRoom() (emissive quads, a glossy floor), AddIsosurfaceRoom() (an isosurface of
 * VTK's wavelet coloured by height, in a room) and AddGlyphField() (boxes glyphed on a ground
 * plane, a directional sun and a uniform sky that the ambient term stands for),
 * AddEmissiveBox() (a closed box lit only by an emissive ceiling panel, seen from inside, no
 * vtkLight) and AddStreamlines() (stream tubes of a vortex coloured by integration time
 * through a lookup table, over a floor, under a sun and a point light).
 * Emitters are drawn by VTK at their emitted radiance (their ambient colour).
 *
 * @sa vtkVoxelGIPass
 */
#ifndef vtkVoxelGIScenes_h
#define vtkVoxelGIScenes_h

#include "vtkObject.h"
#include "vtkSmartPointer.h"          // for vtkSmartPointer
#include "vtkTestingVoxelGIModule.h" // for export macro

class vtkActor;
class vtkAlgorithm;
class vtkRenderer;
class vtkVolume;

class VTKTESTINGVOXELGI_EXPORT vtkVoxelGIScenes : public vtkObject
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

  static void AddGlossyRoom(vtkRenderer* renderer);
  static void AddIsosurfaceRoom(vtkRenderer* renderer);
  static void AddGlyphField(vtkRenderer* renderer);
  static void AddEmissiveBox(vtkRenderer* renderer);
  static void AddStreamlines(vtkRenderer* renderer);
  /**
   * A black, absorbing homogeneous volume (a slab of opacity 0.6 per unit length, GPU ray
   * cast) floating over a floor with a box and a sphere, under a sun and a sky: its shadow
   * and the occlusion it adds are what the reference and the pass must agree on.
   */
  static void AddVolumeSlab(vtkRenderer* renderer);

  /**
   * Scenes nobody tuned the pass to. A closed 10 x 6 x 10 room (white walls, one red, a grey
   * floor, a table with an isosurface coloured through a lookup table) under one point light
   * of inverse-square attenuation ("pointroom").
   */
  static void AddPointLightRoom(vtkRenderer* renderer);
  /**
   * A small closed room of darker albedo (0.5, one blue wall) under a point light of VTK's
   * default attenuation ("lamproom").
   */
  static void AddLampRoom(vtkRenderer* renderer);
  /**
   * A closed room lit only by a small emissive cube hanging in it ("emitterroom").
   */
  static void AddEmitterRoom(vtkRenderer* renderer);
  /**
   * An orange homogeneous volume (opacity 0.5 per unit length, unshaded) floating in a closed
   * white room lit only by an emissive ceiling panel ("volumeroom"): the volume shows the
   * room's light it scatters, shades the floor and bleeds its colour.
   */
  static void AddVolumeRoom(vtkRenderer* renderer);
  /**
   * Contacts: a floor against a wall with a finned heat sink, three touching spheres, a
   * column against the wall and a block, under a point light ("contacts") or VTK's
   * headlight ("contactsheadlight"). Seams, fins and touching points must darken.
   */
  static void AddContacts(vtkRenderer* renderer, bool headlight);
  /**
   * Translucent surfaces under a sun: a blue glass canopy (opacity 0.5) over a white block
   * and an orange glass ball (opacity 0.4) beside an opaque red ball, on a floor against a
   * wall ("translucent"). Their shadows pass (1 - opacity) of the light, in their colour.
   */
  static void AddTranslucentSurfaces(vtkRenderer* renderer);

  /**
   * Add the scene called `name`: "cornell", "glossy", "isosurface", "glyphs", "emissive",
   * "streamlines", "volume", "pointroom", "lamproom", "emitterroom", "volumeroom", "contacts",
   * "contactsheadlight" or "translucent". Returns false (and adds nothing) for another name.
   */
  static bool AddScene(vtkRenderer* renderer, const char* name);

  /**
   * Whether VTK draws part of `renderer`'s scene over the pass's composite (volumes and
   * translucent actors, in its volumetric and translucent steps): then the window's image,
   * not the composite, is what a reference shows.
   */
  static bool DrawsOverComposite(vtkRenderer* renderer);

  /**
   * Add an actor drawing `source`'s polygonal output in colour (r, g, b) to `renderer`, and
   * return it (owned by the renderer).
   */
  static vtkActor* AddSource(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g,
    double b);

  /**
   * A homogeneous volume over `bounds`: constant scalars through constant transfer functions
   * of opacity `alpha` per unit distance and colour `color`, GPU ray cast unshaded.
   */
  static vtkSmartPointer<vtkVolume> MakeHomogeneousVolume(
    const double bounds[6], double alpha, const double color[3]);

protected:
  vtkVoxelGIScenes() = default;
  ~vtkVoxelGIScenes() override = default;

private:
  vtkVoxelGIScenes(const vtkVoxelGIScenes&) = delete;
  void operator=(const vtkVoxelGIScenes&) = delete;
};

#endif
