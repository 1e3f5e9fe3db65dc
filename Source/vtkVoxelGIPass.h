/**
 * @class   vtkVoxelGIPass
 * @brief   Real-time voxel global illumination (deferred voxel shading) as a render pass.
 *
 * vtkVoxelGIPass wraps VTK's normal render steps (its delegate pass, by default a
 * vtkRenderStepsPass) and adds voxel global illumination around them. Each frame it scans
 * the renderer's actors and, only when something changed, voxelizes them into 3D volumes of
 * albedo, normal and emission. Voxelization renders every visible opaque surface actor
 * through its own VTK mapper with shader replacements from this pass, so scalar colouring
 * with a lookup table, textures, per-actor colour and transforms voxelize with the colour
 * VTK shows. Rasterization is conservative (no voxel a triangle touches is missed) and the
 * per-voxel averages are exact integer sums that do not overflow.
 *
 * The voxels are then lit (every vtkLight kind VTK renders, occluded through shadow maps or
 * voxel shadows, plus emission), filtered into anisotropic mipmaps, optionally bounced, and
 * cone-traced per pixel from a G-buffer: indirect diffuse light, a specular cone, ambient
 * occlusion and the lights' shadows (shadow maps, or cones) are composited with VTK's own
 * shading of the opaque geometry. Translucent,
 * volume and overlay props are then rendered by VTK's normal steps on top; translucent
 * actors and volumes are in the voxels too, with the partial occupancy of their opacity.
 *
 * Actors are static unless marked dynamic (SetPropDynamic()) or, with AutoDynamic on,
 * once they change after having been voxelized: dynamic actors are revoxelized alone while
 * the static voxels are kept.
 *
 * The settings (SetVoxelResolution(), SetBounces(), ...: name, range, default and documentation)
 * are declared by the base class vtkVoxelGIPassSettings, generated from the settings table
 * Source/VoxelGISettings.json.
 *
 * With Enabled off, the pass renders exactly what its delegate renders. GI needs OpenGL 4.3
 * (compute shaders, image load/store, shader storage buffers); on an older context the pass
 * reports it once and keeps rendering VTK's image.
 *
 * @code
 * vtkVoxelGIPass* gi = vtkVoxelGIPass::New();
 * renderer->SetPass(gi);
 * gi->Delete(); // the renderer holds it
 * gi->SetVoxelResolution(128);
 * renderWindow->Render();
 * @endcode
 *
 * @sa vtkVoxelGIPassSettings vtkVoxelGISettings vtkSSAOPass vtkRenderStepsPass
 */
#ifndef vtkVoxelGIPass_h
#define vtkVoxelGIPass_h

#include "vtkRenderingVoxelGIModule.h" // for export macro
#include "vtkVoxelGIPassSettings.h"    // base class: the settings, generated from their table

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkActor;
class vtkFloatArray;
class vtkImageData;
class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;
class vtkProp;
class vtkRenderPass;
class vtkRenderStepsPass;
class vtkOpenGLRenderWindow;
class vtkRenderWindow;
namespace voxelgi
{
struct Configuration;
struct FramePlan;
struct VoxelView;
}

class VTKRENDERINGVOXELGI_EXPORT vtkVoxelGIPass : public vtkVoxelGIPassSettings
{
public:
  static vtkVoxelGIPass* New();
  vtkTypeMacro(vtkVoxelGIPass, vtkVoxelGIPassSettings);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Render VTK's image through the delegate and the GI stages around it.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Release the GPU volumes, programs and the delegate's resources.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The pass that renders VTK's own image (default: a vtkRenderStepsPass). Without one
   * nothing is drawn, and the pass says so once.
   */
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  ///@{
  /**
   * Share the voxel grid of another pass (set on another renderer of the same window, e.g.
   * another viewport on the same props): this pass then scans, voxelizes, lights and bounces
   * nothing and allocates no voxel volume; it traces the source's voxels for its own
   * renderer's G-buffer, with its own cone, trace and debug-view settings. The voxel settings
   * (resolution, padding, update policy, light occlusion, bounces, mipmaps) and the lights
   * that light the voxels are the source's; this renderer's lights shade VTK's image and aim
   * the shadow cones. The source's renderer should render first (added to the window first,
   * or on a lower layer); otherwise this pass traces the voxels of the source's last frame.
   * The source must own its voxels (no chains: a pass others share cannot share another's)
   * and render into the same window, in each of its renders; otherwise this pass says so
   * once and renders VTK's image (as it does for a frame where the source has released its
   * voxels). nullptr (default): own voxels.
   */
  virtual void SetVoxelSource(vtkVoxelGIPass* source);
  vtkGetObjectMacro(VoxelSource, vtkVoxelGIPass);
  ///@}

  /**
   * Rebuild the voxels (fully) at the next render, whatever the update policy; after a
   * refusal (e.g. too little memory), try the same settings again.
   */
  void Invalidate();

  /**
   * In a distributed render (MPI ranks, e.g. ParaView in parallel), the part of a frame the
   * ranks do together: agreeing to run GI, scanning, and merging the voxels. Compositors skip
   * a rank's Render() when it has nothing in view (IceT does), and a collective call then
   * waits for it forever: call this on every rank at the start of every frame of `renderer`
   * (ParaView's Voxel GI view does, at the renderer's StartEvent); Render() then takes its
   * results. Without it Render() does this part itself, which holds where every rank renders
   * every frame. Does nothing in one process.
   */
  void RenderRanks(vtkRenderer* renderer);

  /**
   * Whether the last voxelization used the hardware conservative rasterizer.
   */
  bool GetUsedHardwareConservativeRaster() const;

  /**
   * The property key that holds a prop's emission (see SetPropEmission()).
   */
  static vtkInformationDoubleVectorKey* EMISSION();

  /**
   * Make `prop` emit linear RGB radiance (r, g, b) (all 0: not emissive), stored in its
   * property keys and read by this pass. Negative or non-finite values are rejected.
   */
  static void SetPropEmission(vtkProp* prop, double r, double g, double b);

  /**
   * The property key that marks a prop dynamic (see SetPropDynamic()).
   */
  static vtkInformationIntegerKey* DYNAMIC();

  /**
   * Mark a prop as dynamic (revoxelized alone whenever it changes) or static.
   */
  static void SetPropDynamic(vtkProp* prop, bool dynamic);

  enum Stages
  {
    STAGE_SCAN = 0,
    STAGE_CLEAR,
    STAGE_VOXELIZE_STATIC,
    STAGE_VOXELIZE_DYNAMIC,
    STAGE_VOLUMES,
    STAGE_RESOLVE,
    STAGE_SHADOW_MAPS,
    STAGE_LIGHT,
    STAGE_MIPMAP,
    STAGE_BOUNCE,
    STAGE_GBUFFER,
    STAGE_CONE_TRACE,
    STAGE_COMPOSITE,
    STAGE_PRESENT,
    STAGE_DEBUG_VIEW,
    NUMBER_OF_STAGES
  };

  /**
   * Whether a stage ran in the last frame, its time in milliseconds and its name. SCAN (the
   * CPU scene scan) is always timed, on the CPU; the others are GPU times, measured only with
   * TimeStages on (0 otherwise). When nothing changed, not even the camera, the last traced
   * image is presented again: only SCAN and PRESENT run.
   */
  bool GetStageRan(int stage) const;
  double GetStageTime(int stage) const;
  static const char* GetStageName(int stage);

  /**
   * True when the last frame's cone tracing reused the frame before it (TemporalReuse, a
   * frame where only the camera moved): one tile in four was traced, the rest reprojected.
   */
  bool GetTraceReused() const;

  /**
   * True when the window's last render ran this pass's GI stages (false when GI was off, could
   * not run on this context, the scene had nothing to voxelize, or the pass did not render in
   * it: its renderer not drawn or the pass removed). A rank of a distributed render whose
   * Render() the compositor skipped reports its part in the ranks' voxels (RenderRanks).
   */
  bool GetGIActive() const;

  /**
   * True when the frames run in the software profile (SoftwareProfile ON, or AUTO on a
   * context whose renderer runs on the CPU, as far as the last frame's context showed).
   */
  bool GetSoftwareProfileActive() const;

  /**
   * The voxel grid of the last frame: voxels per axis (0 before the first voxelization),
   * world position of its minimum corner and voxel edge length.
   */
  int GetGridResolution() const;
  void GetGridOrigin(double origin[3]) const;
  double GetGridVoxelSize() const;

  /**
   * GPU memory held by the voxel volumes and buffers, in bytes.
   */
  unsigned long long GetVoxelMemoryBytes() const;

  /**
   * GPU memory the voxel volumes and the shadow maps need with the current settings, in
   * bytes (the maps of the last frame's lights, at ShadowMapResolution): what
   * GetVoxelMemoryBytes() reports once a scene with (or without) emissive props has been
   * rendered with those lights. Before allocating the volumes, the pass compares what they
   * need with the memory the GL reports free; volumes that do not fit are refused with one
   * error and VTK's image is rendered until a setting changes or Invalidate() is called.
   * Shadow maps that do not fit degrade instead: rendered smaller, or (where not even 128
   * texels fit) replaced by shadows raymarched through the voxels, with one warning that
   * gives the figures.
   */
  unsigned long long GetRequiredVoxelMemoryBytes(bool emission);

  /**
   * Distributed rendering (ParaView's pvbatch or pvserver under MPI, through VTK's global
   * vtkMultiProcessController): the bytes this rank contributed to the reductions of the
   * last frame (decisions, grid bounds, and in a voxelizing frame the voxelization sums), and
   * the milliseconds they took. 0 with one process.
   */
  double GetRankTrafficBytes() const;
  double GetRankTrafficMilliseconds() const;

  enum Resources
  {
    RESOURCE_VOXELIZATION = 0, ///< accumulators, flags, albedo and normal volumes
    RESOURCE_EMISSION,         ///< emission accumulators and volume (emissive scenes only)
    RESOURCE_RADIANCE,         ///< the radiance volume (with mips when isotropic)
    RESOURCE_DIRECT,           ///< direct light kept for bounces (Bounces > 0 only)
    RESOURCE_DIRECTIONAL,      ///< the six anisotropic volumes (anisotropic mipmaps only)
    RESOURCE_SHADOW_MAPS,      ///< shadow maps (LIGHT_OCCLUSION_SHADOW_MAPS only)
    RESOURCE_SCENE_BUFFERS     ///< the actors' triangles compute voxelization reads, the
                               ///< volumes' textures, voxels and incident light (scene-sized,
                               ///< not in GetVoxelMemoryBytes())
  };

  /**
   * GPU memory of one kind of resource, in bytes: 0 when the scene or the settings do not
   * need it (it is then not allocated).
   */
  unsigned long long GetAllocatedBytes(int resource) const;

  enum Volumes
  {
    VOLUME_ALBEDO = 0, ///< unsigned char RGBA, alpha the share of light stopped (255: opaque)
    VOLUME_NORMAL,     ///< unsigned char RGBA, normal * 127.5 + 127.5
    VOLUME_EMISSION,   ///< float RGBA (only when the scene has emission)
    VOLUME_COUNT,      ///< unsigned int: fragments averaged into each voxel
    VOLUME_FLAG,       ///< unsigned char: 1 where a static actor wrote the voxel
    VOLUME_RADIANCE    ///< float RGBA: lit radiance (rgb) and occupancy (a)
  };

  enum Images
  {
    IMAGE_COMPOSITE = 0, ///< the composited linear colour (before clamping for display)
    IMAGE_INDIRECT       ///< indirect diffuse + specular light (rgb) and AO (a)
  };

  /**
   * Copy a float image of the last GI frame (RGBA, the renderer's viewport size, rows bottom
   * to top) into `pixels`. Returns false when the last frame did not trace.
   */
  bool GetFloatImage(int image, vtkFloatArray* pixels);

  /**
   * Copy a voxel volume of the last frame into `image` (point data "Voxels"; origin at the
   * first voxel's centre, spacing the voxel size). Makes the last render window's context
   * current. Returns false when there is no such volume.
   */
  bool GetVoxelVolume(int volume, vtkImageData* image);

protected:
  vtkVoxelGIPass();
  ~vtkVoxelGIPass() override;

  ///@{
  /// The frame plan (FramePlan.h, built by FramePlanner): whether GI runs and what each
  /// stage does. PlanVoxels is the ranks' part (the gate, the ranks' agreement, the scan);
  /// FollowSource plans from the VoxelSource's voxels (FramePlanner::PlanSource).
  voxelgi::FramePlan& PlanFrame(const vtkRenderState* s);
  voxelgi::FramePlan& PlanVoxels(vtkRenderer* renderer, const vtkRenderState* s);
  bool FollowSource();
  ///@}

  ///@{
  /// The stages, as the plan says; false where a stage cannot run (refused: GI is off).
  /// Voxelize: the voxels. Relight: ShadowMaps, LightVoxels, Mipmap, Bounce. Trace:
  /// GBuffer, ConeTrace, Composite (or a voxel debug view). Present: the GI image and VTK's
  /// remaining steps, or VTK's image alone.
  bool Voxelize();
  bool Relight();
  bool Trace();
  void Present();
  ///@}

  /// Whether the pass serves `renderer` (Gate::Serve); a new renderer forgets the last one's
  /// voxels and images.
  bool Serve(vtkRenderer* renderer);
  /// Render VTK's own image.
  void RenderDelegate(const vtkRenderState* s);
  /// The frame's configuration, as refusals are remembered.
  voxelgi::Configuration Configuration();
  /// A stage could not be prepared: say why once, free every GL resource of the stages and
  /// render VTK's image until a setting, the scene's emission or the viewport changes.
  void Refuse(const std::string& error);
  /// A read-only view of this pass's voxels; TracedVoxels: of those it traces (its
  /// VoxelSource's, or its own).
  voxelgi::VoxelView ViewVoxels() const;
  voxelgi::VoxelView TracedVoxels() const;
  /// Free the GL resources of every stage (not the delegate's).
  void ReleaseStages(vtkWindow* w);
  /// Free the voxel volumes and the stages that fill them.
  void ReleaseVoxelStages(vtkWindow* w);

  vtkRenderPass* DelegatePass = nullptr;
  vtkVoxelGIPass* VoxelSource = nullptr;
  bool GIActive = false;

private:
  vtkVoxelGIPass(const vtkVoxelGIPass&) = delete;
  void operator=(const vtkVoxelGIPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
