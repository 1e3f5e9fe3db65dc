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
 * volume and overlay props are then rendered by VTK's normal steps on top.
 *
 * Actors are static unless marked dynamic (SetPropDynamic()) or, with AutoDynamic on,
 * once they change after having been voxelized: dynamic actors are revoxelized alone while
 * the static voxels are kept.
 *
 * With Enabled off, the pass renders exactly what its delegate renders. GI needs OpenGL 4.3
 * (compute shaders, image load/store, shader storage buffers); on an older context the pass
 * reports it once and keeps rendering VTK's image.
 *
 * @code
 * vtkNew<vtkVoxelGIPass> gi;
 * renderer->SetPass(gi);
 * gi->SetVoxelResolution(128);
 * renderWindow->Render();
 * @endcode
 *
 * @sa vtkSSAOPass vtkRenderStepsPass
 */
#ifndef vtkVoxelGIPass_h
#define vtkVoxelGIPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingVoxelGIModule.h" // for export macro

#include <cmath>  // for std::isnan
#include <memory> // for std::unique_ptr
#include <string> // for std::string

// vtkSetClampMacro that refuses NaN (which passes any clamp) with a message naming the
// setting, keeping its value.
#define vtkVoxelGISetClampMacro(name, type, min, max)                                          \
  virtual void Set##name(type _arg)                                                            \
  {                                                                                            \
    if (std::isnan(_arg))                                                                      \
    {                                                                                          \
      vtkWarningMacro(<< #name " cannot be NaN; it stays " << this->name << ".");             \
      return;                                                                                  \
    }                                                                                          \
    const type clamped = _arg < min ? min : (_arg > max ? max : _arg);                         \
    if (this->name != clamped)                                                                 \
    {                                                                                          \
      this->name = clamped;                                                                    \
      this->Modified();                                                                        \
    }                                                                                          \
  }                                                                                            \
  virtual type Get##name##MinValue() { return min; }                                           \
  virtual type Get##name##MaxValue() { return max; }

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

class VTKRENDERINGVOXELGI_EXPORT vtkVoxelGIPass : public vtkOpenGLRenderPass
{
public:
  static vtkVoxelGIPass* New();
  vtkTypeMacro(vtkVoxelGIPass, vtkOpenGLRenderPass);
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
   * The source must own its voxels (no chains) and render into the same window; otherwise
   * this pass says so once and renders VTK's image. nullptr (default): own voxels.
   */
  virtual void SetVoxelSource(vtkVoxelGIPass* source);
  vtkGetObjectMacro(VoxelSource, vtkVoxelGIPass);
  ///@}

  ///@{
  /**
   * Turn global illumination on or off. Off renders exactly what the delegate renders and
   * does no voxel work. Default: on.
   */
  vtkSetMacro(Enabled, vtkTypeBool);
  vtkGetMacro(Enabled, vtkTypeBool);
  vtkBooleanMacro(Enabled, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Voxels per axis of the voxel grid: a power of two in [16, 512] (other values are
   * rounded to the nearest one). Memory grows with its cube: about 60 bytes per voxel, 84
   * in scenes with emissive props (128: 120 / 168 MiB, 256: 959 / 1343 MiB; see
   * GetRequiredVoxelMemoryBytes()). Default: 128.
   */
  virtual void SetVoxelResolution(int resolution);
  vtkGetMacro(VoxelResolution, int);
  ///@}

  ///@{
  /**
   * Space left around the scene in the voxel grid, as a fraction of the scene's largest
   * extent on each side, in [0, 0.5]. Default: 0.05.
   */
  vtkVoxelGISetClampMacro(GridPadding, double, 0.0, 0.5);
  vtkGetMacro(GridPadding, double);
  ///@}

  enum DebugViews
  {
    DEBUG_VIEW_NONE = 0,
    DEBUG_VIEW_VOXEL_ALBEDO = 1,
    DEBUG_VIEW_VOXEL_NORMAL = 2,
    DEBUG_VIEW_VOXEL_EMISSION = 3,
    DEBUG_VIEW_VOXEL_RADIANCE = 4,
    DEBUG_VIEW_DIRECT = 5,
    DEBUG_VIEW_INDIRECT = 6,
    DEBUG_VIEW_AMBIENT_OCCLUSION = 7
  };

  ///@{
  /**
   * Show an intermediate result instead of the composited image. Voxel views show the first
   * voxel along each camera ray: its albedo, normal (xyz mapped to rgb), emission or lit
   * radiance (tone mapped e / (1 + e)). DIRECT shows VTK's shading with the cone shadows and
   * AO applied, INDIRECT the indirect diffuse and specular light alone, AMBIENT_OCCLUSION the
   * cone-traced AO. Default: DEBUG_VIEW_NONE.
   */
  vtkSetClampMacro(DebugView, int, DEBUG_VIEW_NONE, DEBUG_VIEW_AMBIENT_OCCLUSION);
  vtkGetMacro(DebugView, int);
  void SetDebugViewToNone() { this->SetDebugView(DEBUG_VIEW_NONE); }
  void SetDebugViewToVoxelAlbedo() { this->SetDebugView(DEBUG_VIEW_VOXEL_ALBEDO); }
  void SetDebugViewToVoxelNormal() { this->SetDebugView(DEBUG_VIEW_VOXEL_NORMAL); }
  void SetDebugViewToVoxelEmission() { this->SetDebugView(DEBUG_VIEW_VOXEL_EMISSION); }
  void SetDebugViewToVoxelRadiance() { this->SetDebugView(DEBUG_VIEW_VOXEL_RADIANCE); }
  void SetDebugViewToDirect() { this->SetDebugView(DEBUG_VIEW_DIRECT); }
  void SetDebugViewToIndirect() { this->SetDebugView(DEBUG_VIEW_INDIRECT); }
  void SetDebugViewToAmbientOcclusion() { this->SetDebugView(DEBUG_VIEW_AMBIENT_OCCLUSION); }
  ///@}

  enum LightOcclusionModes
  {
    LIGHT_OCCLUSION_NONE = 0,
    LIGHT_OCCLUSION_VOXEL_SHADOWS = 1,
    LIGHT_OCCLUSION_SHADOW_MAPS = 2
  };

  ///@{
  /**
   * How the voxel lighting finds what the lights do not reach. VOXEL_SHADOWS: each voxel
   * marches toward every light through the voxel occupancy (soft voxel shadows).
   * SHADOW_MAPS: every light but a headlight renders depth maps from the geometry
   * (ShadowMapResolution; one for a directional or spot light, the six faces of a cube for a
   * point light), sharper than the voxels, and the pixels' shadows of scene lights are read
   * from the same maps (ConeShadows); all lights of a distributed render raymarch (a rank's
   * maps would see its own piece only). NONE: every voxel facing a light is lit. Default:
   * LIGHT_OCCLUSION_SHADOW_MAPS (the error study: FLIP against Cycles 0.145 -> 0.124 in the
   * glyph field under a sun, 0.167 -> 0.157 under the stream tubes, for 0.3 ms of ShadowMaps
   * per relight on the atrium at 1080p).
   */
  vtkSetClampMacro(LightOcclusion, int, LIGHT_OCCLUSION_NONE, LIGHT_OCCLUSION_SHADOW_MAPS);
  vtkGetMacro(LightOcclusion, int);
  void SetLightOcclusionToNone() { this->SetLightOcclusion(LIGHT_OCCLUSION_NONE); }
  void SetLightOcclusionToVoxelShadows() { this->SetLightOcclusion(LIGHT_OCCLUSION_VOXEL_SHADOWS); }
  void SetLightOcclusionToShadowMaps() { this->SetLightOcclusion(LIGHT_OCCLUSION_SHADOW_MAPS); }
  ///@}

  ///@{
  /**
   * Size of each shadow map in texels, in [128, 4096]. Default: 1024.
   */
  vtkSetClampMacro(ShadowMapResolution, int, 128, 4096);
  vtkGetMacro(ShadowMapResolution, int);
  ///@}

  ///@{
  /**
   * Bounces of indirect diffuse light between voxels, in [0, 10]. Each one cone-traces every
   * occupied voxel and rebuilds the mipmaps, in frames whose voxels or lights changed (camera
   * frames reuse the result). Default: 4 (closed rooms need several: the error study's FLIP
   * falls from 0.36 at one bounce to 0.26 at four in the Cornell box).
   */
  vtkSetClampMacro(Bounces, int, 0, 10);
  vtkGetMacro(Bounces, int);
  ///@}

  ///@{
  /**
   * How far camera-following lights (VTK's headlight, camera lights, a light kit) may turn,
   * in degrees in [0, 180], before the voxels are lit and bounced again. Until then a frame
   * that moves the camera traces with the voxel light of the last relight: only the indirect
   * light lags, VTK's direct light follows the camera exactly. 0 relights at every turn.
   * Default: 45 (docs/reference.md gives the error against the turn, docs/performance.md the
   * cost).
   */
  vtkVoxelGISetClampMacro(CameraLightTurn, double, 0.0, 180.0);
  vtkGetMacro(CameraLightTurn, double);
  ///@}

  ///@{
  /**
   * Most samples per pixel of the G-buffer, in [0, 16], in a multisampled window: VTK draws
   * its opaque geometry with the window's count up to this, resolved before tracing, so that
   * edges, lines on surfaces and thin text keep VTK's anti-aliasing. 0 or 1: one sample
   * (edges aliased). Default: 0 (docs/performance.md gives the cost).
   */
  vtkSetClampMacro(GBufferSamples, int, 0, 16);
  vtkGetMacro(GBufferSamples, int);
  ///@}

  ///@{
  /**
   * Anisotropic mipmaps (six directional volumes) rather than one isotropic mip chain:
   * less light leaking through thin walls, 6/8 more memory. Default: on.
   */
  vtkSetMacro(AnisotropicMipmaps, vtkTypeBool);
  vtkGetMacro(AnisotropicMipmaps, vtkTypeBool);
  vtkBooleanMacro(AnisotropicMipmaps, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Diffuse cones per pixel (and per voxel for bounces), in [1, 16], spread with a cosine
   * distribution over the normal's hemisphere. Default: 16.
   */
  vtkSetClampMacro(DiffuseConeCount, int, 1, 16);
  vtkGetMacro(DiffuseConeCount, int);
  ///@}

  ///@{
  /**
   * Full aperture of the diffuse cones in degrees, in [5, 120]. Default: 60.
   */
  vtkVoxelGISetClampMacro(DiffuseConeAperture, double, 5.0, 120.0);
  vtkGetMacro(DiffuseConeAperture, double);
  ///@}

  ///@{
  /**
   * Cone step length as a fraction of the cone's diameter, in [0.05, 2]: smaller is finer
   * and slower (opacity is corrected for the step). Default: 0.75.
   */
  vtkVoxelGISetClampMacro(ConeStepFactor, double, 0.05, 2.0);
  vtkGetMacro(ConeStepFactor, double);
  ///@}

  ///@{
  /**
   * Longest cone, as a fraction of the voxel grid's size, in [0, 2]. 0 traces nothing.
   * Default: 1.75, across the grid's diagonal, so that no cone stops inside a closed room.
   */
  vtkVoxelGISetClampMacro(MaxTraceDistance, double, 0.0, 2.0);
  vtkGetMacro(MaxTraceDistance, double);
  ///@}

  ///@{
  /**
   * How far cones start from the surface, in voxels along the normal, in [0, 8]: keeps a
   * surface from lighting itself through its own voxels. Default: 1.5.
   */
  vtkVoxelGISetClampMacro(ConeStartOffset, double, 0.0, 8.0);
  vtkGetMacro(ConeStartOffset, double);
  ///@}

  ///@{
  /**
   * Resolution of the per-pixel cone tracing relative to the image, in [0.25, 1]. Below 1
   * the traced light is upsampled edge-aware (weighted by position and normal similarity)
   * when composited: 0.5 traces a quarter of the pixels. Default: 1.
   */
  vtkVoxelGISetClampMacro(TraceResolution, double, 0.25, 1.0);
  vtkGetMacro(TraceResolution, double);
  ///@}

  ///@{
  /**
   * Temporal reuse: in frames where only the camera moved, trace one tile of the image in
   * four (rotating, so every pixel is re-traced at least every fourth frame) and take the
   * others from the previous frame at their reprojected surface, except where that surface
   * differs (position, normal, or the view direction of a specular surface): those are
   * traced too. Any change of the voxels, the lights or the settings traces everything. Off
   * traces every pixel every frame. Default: on.
   */
  vtkSetMacro(TemporalReuse, vtkTypeBool);
  vtkGetMacro(TemporalReuse, vtkTypeBool);
  vtkBooleanMacro(TemporalReuse, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Scale of the indirect diffuse light, in [0, 10]. Default: 1.
   */
  vtkVoxelGISetClampMacro(IndirectIntensity, double, 0.0, 10.0);
  vtkGetMacro(IndirectIntensity, double);
  ///@}

  ///@{
  /**
   * One specular cone per pixel for glossy reflections, its aperture following the
   * material's specular power (vtkProperty::SpecularPower). Default: on.
   */
  vtkSetMacro(SpecularCone, vtkTypeBool);
  vtkGetMacro(SpecularCone, vtkTypeBool);
  vtkBooleanMacro(SpecularCone, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Scale of the indirect specular light, in [0, 10]. Default: 1.
   */
  vtkVoxelGISetClampMacro(SpecularIntensity, double, 0.0, 10.0);
  vtkGetMacro(SpecularIntensity, double);
  ///@}

  ///@{
  /**
   * How much the cone-traced ambient occlusion darkens VTK's ambient term (the property's
   * ambient coefficient times its ambient colour), in [0, 1] (0: AO off). The lights' direct
   * light, the cone-traced indirect light (occluded by the cones themselves) and emitters'
   * light are never darkened by it. Default: 1 (the ambient term stands for light from all
   * around, which occluders block entirely).
   */
  vtkVoxelGISetClampMacro(AmbientOcclusionStrength, double, 0.0, 1.0);
  vtkGetMacro(AmbientOcclusionStrength, double);
  ///@}

  ///@{
  /**
   * Falloff of occluders' weight with distance in the AO, per voxel, in [0, 10]: an
   * occluder t voxels away counts 1 / (1 + falloff t). Default: 0.05.
   */
  vtkVoxelGISetClampMacro(AmbientOcclusionFalloff, double, 0.0, 10.0);
  vtkGetMacro(AmbientOcclusionFalloff, double);
  ///@}

  ///@{
  /**
   * Shadows of the lights (headlights excepted) in the pixels: the occluded part of each
   * light's contribution is removed from VTK's shading. A scene light with a shadow map
   * (LightOcclusion SHADOW_MAPS) is looked up there, filtered over 3 x 3 texels; other lights
   * (camera lights, whose maps lag while they turn, every light of a distributed render, and
   * the lights of a pass that shares another's voxels unless they are the other's lights)
   * trace a cone through the voxels
   * (ShadowConeAperture). Default: on.
   */
  vtkSetMacro(ConeShadows, vtkTypeBool);
  vtkGetMacro(ConeShadows, vtkTypeBool);
  vtkBooleanMacro(ConeShadows, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Full aperture of the shadow cones (lights without a pixel shadow map, see ConeShadows) in
   * degrees, in [0.5, 60]: wider is softer. Default: 1
   * (the error study: the sharpest shadows are the closest to Cycles' in every lit scene;
   * 6 -> 1 took the isosurface room's FLIP 0.326 -> 0.280 and the stream tubes' 0.167 ->
   * 0.127, for +0.06 to +0.2 ms of ConeTrace per 1080p frame).
   */
  vtkVoxelGISetClampMacro(ShadowConeAperture, double, 0.5, 60.0);
  vtkGetMacro(ShadowConeAperture, double);
  ///@}

  ///@{
  /**
   * Treat an actor that changes after it was voxelized as dynamic from then on, so later
   * changes revoxelize it alone instead of the whole scene. Default: on.
   */
  vtkSetMacro(AutoDynamic, vtkTypeBool);
  vtkGetMacro(AutoDynamic, vtkTypeBool);
  vtkBooleanMacro(AutoDynamic, vtkTypeBool);
  ///@}

  enum UpdatePolicies
  {
    UPDATE_ON_CHANGE = 0,
    UPDATE_EVERY_FRAME = 1,
    UPDATE_EVERY_N_FRAMES = 2,
    UPDATE_ON_DEMAND = 3
  };

  ///@{
  /**
   * When the voxels are rebuilt. ON_CHANGE: whenever an actor, mapper, input, property or
   * transform changed (only the changed dynamic actors when possible). EVERY_FRAME: a full
   * revoxelization every frame. EVERY_N_FRAMES: changes are picked up at most every
   * UpdateInterval frames. ON_DEMAND: only after Invalidate(). Changes of the voxel settings
   * (resolution, padding) always rebuild. Lights and camera are followed every frame whatever
   * the policy. Default: UPDATE_ON_CHANGE.
   */
  vtkSetClampMacro(UpdatePolicy, int, UPDATE_ON_CHANGE, UPDATE_ON_DEMAND);
  vtkGetMacro(UpdatePolicy, int);
  void SetUpdatePolicyToOnChange() { this->SetUpdatePolicy(UPDATE_ON_CHANGE); }
  void SetUpdatePolicyToEveryFrame() { this->SetUpdatePolicy(UPDATE_EVERY_FRAME); }
  void SetUpdatePolicyToEveryNFrames() { this->SetUpdatePolicy(UPDATE_EVERY_N_FRAMES); }
  void SetUpdatePolicyToOnDemand() { this->SetUpdatePolicy(UPDATE_ON_DEMAND); }
  ///@}

  ///@{
  /**
   * Frames between updates for UPDATE_EVERY_N_FRAMES, in [1, 1000]. Default: 10.
   */
  vtkSetClampMacro(UpdateInterval, int, 1, 1000);
  vtkGetMacro(UpdateInterval, int);
  ///@}

  /**
   * Rebuild the voxels (fully) at the next render, whatever the update policy.
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

  ///@{
  /**
   * Rasterize conservatively with the GPU's GL_NV_conservative_raster where the context has
   * it; otherwise (or when off) triangles are dilated in the geometry shader. Both are
   * conservative. Default: on.
   */
  vtkSetMacro(HardwareConservativeRaster, vtkTypeBool);
  vtkGetMacro(HardwareConservativeRaster, vtkTypeBool);
  vtkBooleanMacro(HardwareConservativeRaster, vtkTypeBool);
  ///@}

  /**
   * Whether the last voxelization used the hardware conservative rasterizer.
   */
  bool GetUsedHardwareConservativeRaster() const;

  ///@{
  /**
   * Measure each stage's GPU time with timer queries (GetStageTime()). Waiting for the
   * results costs a little, hence off by default.
   */
  vtkSetMacro(TimeStages, vtkTypeBool);
  vtkGetMacro(TimeStages, vtkTypeBool);
  vtkBooleanMacro(TimeStages, vtkTypeBool);
  ///@}

  /**
   * Emission of a prop, as linear RGB radiance (0 or absent: not emissive). Stored in the
   * prop's property keys, read by this pass. Negative or non-finite values are rejected.
   */
  static vtkInformationDoubleVectorKey* EMISSION();
  static void SetPropEmission(vtkProp* prop, double r, double g, double b);

  /**
   * Mark a prop as dynamic (revoxelized alone whenever it changes) or static.
   */
  static vtkInformationIntegerKey* DYNAMIC();
  static void SetPropDynamic(vtkProp* prop, bool dynamic);

  enum Stages
  {
    STAGE_SCAN = 0,
    STAGE_CLEAR,
    STAGE_VOXELIZE_STATIC,
    STAGE_VOXELIZE_DYNAMIC,
    STAGE_RESOLVE,
    STAGE_SHADOW_MAPS,
    STAGE_LIGHT,
    STAGE_MIPMAP,
    STAGE_BOUNCE,
    STAGE_GBUFFER,
    STAGE_CONE_TRACE,
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
   * True when the last frame ran the GI stages (false when GI was off, could not run on this
   * context, or the scene had nothing to voxelize). A rank of a distributed render whose
   * Render() the compositor skipped reports its part in the ranks' voxels (RenderRanks).
   */
  vtkGetMacro(GIActive, bool);

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
   * GPU memory the voxel volumes need with the current settings, in bytes: what
   * GetVoxelMemoryBytes() reports once a scene with (or without) emissive props has been
   * rendered, shadow maps not included. Before allocating, the pass compares it with the
   * memory the GL reports free; a configuration that does not fit is refused with one error
   * and renders VTK's image until a setting changes.
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
    RESOURCE_SHADOW_MAPS       ///< shadow maps (LIGHT_OCCLUSION_SHADOW_MAPS only)
  };

  /**
   * GPU memory of one kind of resource, in bytes: 0 when the scene or the settings do not
   * need it (it is then not allocated).
   */
  unsigned long long GetAllocatedBytes(int resource) const;

  enum Volumes
  {
    VOLUME_ALBEDO = 0, ///< unsigned char RGBA, alpha 255 where occupied
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

  /// Release everything on the window the pass rendered to last, and follow `window`.
  void WatchWindow(vtkOpenGLRenderWindow* window);
  void WindowDeleted();
  /// Render VTK's own image.
  void RenderDelegate(const vtkRenderState* s);
  /// Whether the frame's viewport fits GL's image size limits (else says so, once per size).
  bool ViewportFits();
  /// Take `renderer` as the one whose voxels and images the pass keeps; false (said once)
  /// when another renderer of the same window still has the pass.
  bool ServeRenderer(vtkRenderer* renderer);
  /// False, with one error, where the render passes around or below this one cannot hold GI.
  bool PassesCombine(vtkRenderer* renderer);
  /// Whether the frame's voxel volumes fit the memory the GL reports free (counting what the
  /// pass holds now); refuses the configuration if not.
  bool MemoryFits(bool emission);
  /// A stage could not be prepared: say why once, free every GL resource of the stages and
  /// render VTK's image until a setting, the scene's emission or the viewport changes.
  void Refuse(const std::string& error);
  /// Whether the frame's configuration was refused before.
  bool Refused() const;
  /// OpenGL 4.3 available? Reports a missing capability once.
  bool CheckContext(vtkRenderWindow* renWin);
  /// Whether GI can run in `renderer` this frame (this process's view); begins the frame.
  bool BeginFrame(vtkRenderer* renderer, const vtkRenderState* s);
  /// The ranks' part of the frame (RanksAgree, UpdateVoxels): whether GI runs.
  bool UpdateShared(bool runs, bool& voxelsChanged);
  /// Scan the scene and bring the voxels up to date (Voxelize stage); false if GI cannot
  /// run. `changed` tells whether any voxel was rewritten.
  bool UpdateVoxels(bool& changed);
  /// Gather the lights; when voxels, lights or settings changed: LightVoxels, Mipmap,
  /// Bounce. False when GI cannot run (nothing lights the scene).
  bool UpdateRadiance(bool voxelsChanged, bool& changed);
  /// Say once when the window anti-aliases lines the one-sample G-buffer draws aliased.
  void NoticeAliasing();
  /// Distributed rendering (MPI ranks): whether every rank `runs` GI this frame (a collective
  /// call; one error where another rank cannot). One process: `runs`.
  bool RanksAgree(bool runs);
  /// Gather the renderer's lights into the light block; false (said once) when neither they
  /// nor `emission` light anything. `changed`: the lights differ from the last frame's.
  bool GatherLights(bool emission, bool& changed);
  /// Trace the VoxelSource's voxels: false (said once where it is this pass's fault) when they
  /// cannot be used. `changed`: they or this renderer's lights changed in a way that a trace
  /// cannot reuse.
  bool FollowSource(bool& changed);
  /// The pass whose voxels this one traces: the VoxelSource, or this pass.
  const vtkVoxelGIPass* VoxelOwner() const;
  /// Light the voxels and bounce; `follow`: only camera lights turned since the last time.
  bool LightAndBounce(bool follow);
  /// GBuffer, ConeTrace and Composite (unless `reuse`: nothing changed since the last traced
  /// frame), then Present and VTK's remaining steps.
  void RenderGI(bool reuse);
  /// GBuffer, ConeTrace, Composite; false (refused) if their images cannot be made.
  bool TraceFrame();
  /// Free the GL resources of every stage (not the delegate's).
  void ReleaseStages(vtkWindow* w);
  /// Free the voxel volumes and the stages that fill them.
  void ReleaseVoxelStages(vtkWindow* w);
  /// A voxel debug view over VTK's image.
  void RenderVoxelView();

  vtkRenderPass* DelegatePass = nullptr;
  vtkVoxelGIPass* VoxelSource = nullptr;
  // Settings: defaults (and ranges) from the settings table, Source/VoxelGISettings.json.
  vtkTypeBool Enabled{};
  int VoxelResolution{};
  double GridPadding{};
  int DebugView{};
  vtkTypeBool AutoDynamic{};
  vtkTypeBool HardwareConservativeRaster{};
  int UpdatePolicy{};
  int UpdateInterval{};
  vtkTypeBool TimeStages{};
  int LightOcclusion{};
  int ShadowMapResolution{};
  int Bounces{};
  double CameraLightTurn{};
  int GBufferSamples{};
  vtkTypeBool AnisotropicMipmaps{};
  int DiffuseConeCount{};
  double DiffuseConeAperture{};
  double ConeStepFactor{};
  double MaxTraceDistance{};
  double ConeStartOffset{};
  double TraceResolution{};
  vtkTypeBool TemporalReuse{};
  double IndirectIntensity{};
  vtkTypeBool SpecularCone{};
  double SpecularIntensity{};
  double AmbientOcclusionStrength{};
  double AmbientOcclusionFalloff{};
  vtkTypeBool ConeShadows{};
  double ShadowConeAperture{};
  bool GIActive = false;

private:
  vtkVoxelGIPass(const vtkVoxelGIPass&) = delete;
  void operator=(const vtkVoxelGIPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
