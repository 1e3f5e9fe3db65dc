#include "StageIds.h"

#include "vtkVoxelGIPass.h"

namespace voxelgi
{
namespace stage
{

const char* Name(int id)
{
  static const char* names[Count] = { "Scan", "Clear", "VoxelizeStatic", "VoxelizeDynamic",
    "Volumes", "Resolve", "ShadowMaps", "LightVoxels", "Mipmap", "Bounce", "GBuffer", "ConeTrace",
    "Composite", "Present", "DebugView" };
  return (id >= 0 && id < Count) ? names[id] : "Unknown";
}

}
}

// The public stage ids are the stages' own (StageIds.h).
static_assert(int(vtkVoxelGIPass::NUMBER_OF_STAGES) == voxelgi::stage::Count, "stage count");
static_assert(int(vtkVoxelGIPass::STAGE_SCAN) == voxelgi::stage::Scan, "Scan");
static_assert(int(vtkVoxelGIPass::STAGE_CLEAR) == voxelgi::stage::Clear, "Clear");
static_assert(
  int(vtkVoxelGIPass::STAGE_VOXELIZE_STATIC) == voxelgi::stage::VoxelizeStatic, "VoxelizeStatic");
static_assert(
  int(vtkVoxelGIPass::STAGE_VOXELIZE_DYNAMIC) == voxelgi::stage::VoxelizeDynamic, "VoxelizeDynamic");
static_assert(int(vtkVoxelGIPass::STAGE_VOLUMES) == voxelgi::stage::Volumes, "Volumes");
static_assert(int(vtkVoxelGIPass::STAGE_RESOLVE) == voxelgi::stage::Resolve, "Resolve");
static_assert(int(vtkVoxelGIPass::STAGE_SHADOW_MAPS) == voxelgi::stage::ShadowMaps, "ShadowMaps");
static_assert(int(vtkVoxelGIPass::STAGE_LIGHT) == voxelgi::stage::LightVoxels, "LightVoxels");
static_assert(int(vtkVoxelGIPass::STAGE_MIPMAP) == voxelgi::stage::Mipmap, "Mipmap");
static_assert(int(vtkVoxelGIPass::STAGE_BOUNCE) == voxelgi::stage::Bounce, "Bounce");
static_assert(int(vtkVoxelGIPass::STAGE_GBUFFER) == voxelgi::stage::GBuffer, "GBuffer");
static_assert(int(vtkVoxelGIPass::STAGE_CONE_TRACE) == voxelgi::stage::ConeTrace, "ConeTrace");
static_assert(int(vtkVoxelGIPass::STAGE_COMPOSITE) == voxelgi::stage::Composite, "Composite");
static_assert(int(vtkVoxelGIPass::STAGE_PRESENT) == voxelgi::stage::Present, "Present");
static_assert(int(vtkVoxelGIPass::STAGE_DEBUG_VIEW) == voxelgi::stage::DebugView, "DebugView");
