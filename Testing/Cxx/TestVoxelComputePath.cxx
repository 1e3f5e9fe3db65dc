// Compute voxelization (ComputeVoxelization on, the default) gives the voxels of the raster
// path through VTK's mappers (off), voxel by voxel, on the scenes the raster path is tested
// with, one case per run:
//
//   TestVoxelComputePath CASE     (CTest runs each as VoxelGI::ComputePath.CASE)
//
// cornell, isosurface (a scalar-coloured isosurface: colours per point through a lookup
// table), glyphs (glyph instances keep the raster path; the floor is read), emissive (the
// Cornell box's panel: emission volume too), cells (a sphere coloured per cell), strips (a
// triangle-strip sphere coloured per point), offset (the scene 1e7 units from the origin:
// positions shifted into floats), dynamic (a dynamic block moved after the first frame: the
// static voxels kept, the block's written again), changing (a sphere whose tessellation, and
// so its number of triangles, changes at every frame, as time-varying data does), follower (a
// scalar-coloured vtkFollower without a camera, as vedo's meshes are). Both paths
// run in one process; the compute run must hold triangle buffers (RESOURCE_SCENE_BUFFERS) and
// the raster run none. The lit voxels must agree too: the compute run draws the scene lights'
// shadow maps from the same resident triangles (ShadowDepth), the raster run through copies
// of the mappers.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkElevationFilter.h"
#include "vtkFollower.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointDataToCellData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Volumes
{
  std::vector<double> Count;
  std::vector<double> Albedo; // RGBA per voxel
  std::vector<double> Normal;
  std::vector<double> Emission;
  std::vector<double> Radiance; // lit: the scene lights' shadow maps drawn from each path
  unsigned long long SceneBytes = 0;
};

std::vector<double> Values(vtkVoxelGIPass* gi, int volume)
{
  vtkNew<vtkImageData> image;
  std::vector<double> values;
  if (!gi->GetVoxelVolume(volume, image))
  {
    return values;
  }
  vtkDataArray* array = image->GetPointData()->GetScalars();
  values.resize(static_cast<std::size_t>(array->GetNumberOfValues()));
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    values[static_cast<std::size_t>(i)] = array->GetVariantValue(i).ToDouble();
  }
  return values;
}

vtkActor* AddColored(vtkRenderer* renderer, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

/// The scene of `which` in `renderer`; false for an unknown case. `step`, where set, changes
/// the scene between frames.
bool Build(const std::string& which, vtkRenderer* renderer, std::function<void(int)>& step)
{
  if (which == "cornell" || which == "emissive")
  {
    vtkVoxelGIScenes::AddCornellBox(renderer, which == "emissive" ? 4.0 : 0.0);
    return true;
  }
  if (which == "isosurface" || which == "glyphs")
  {
    return vtkVoxelGIScenes::AddScene(renderer, which.c_str());
  }
  voxelgi_test::AddSphereAndBlockOnFloor(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  sphere->SetCenter(-1.5, 1.0, 1.0);
  sphere->SetRadius(0.8);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(0.0, 0.2, 0.0);
  elevation->SetHighPoint(0.0, 1.8, 0.0);
  if (which == "cells")
  {
    vtkNew<vtkPointDataToCellData> cells;
    cells->SetInputConnection(elevation->GetOutputPort());
    AddColored(renderer, cells);
    return true;
  }
  if (which == "strips")
  {
    vtkNew<vtkStripper> strips;
    strips->SetInputConnection(elevation->GetOutputPort());
    AddColored(renderer, strips);
    return true;
  }
  if (which == "offset")
  {
    AddColored(renderer, elevation);
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp())
    {
      if (auto* actor = vtkActor::SafeDownCast(prop))
      {
        actor->AddPosition(1e7, -1e7, 1e7);
      }
    }
    renderer->ResetCamera();
    return true;
  }
  if (which == "dynamic")
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetBounds(-0.4, 0.4, 0.0, 0.8, -2.0, -1.2);
    vtkActor* moving = vtkVoxelGIScenes::AddSource(renderer, cube, 0.9, 0.8, 0.1);
    vtkVoxelGIPass::SetPropDynamic(moving, true);
    step = [moving](int) { moving->AddPosition(0.35, 0.0, 0.45); };
    return true;
  }
  if (which == "follower")
  {
    // A follower without a camera (every vedo mesh), placed by its position.
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(elevation->GetOutputPort());
    mapper->SetScalarRange(0.0, 1.0);
    vtkNew<vtkFollower> follower;
    follower->SetMapper(mapper);
    follower->SetPosition(0.3, 0.1, -0.4);
    renderer->AddActor(follower);
    return true;
  }
  if (which == "changing")
  {
    vtkSmartPointer<vtkSphereSource> changing = sphere.Get();
    AddColored(renderer, elevation);
    step = [changing](int frame) {
      changing->SetThetaResolution(12 + 9 * frame);
      changing->SetPhiResolution(7 + 5 * frame);
    };
    return true;
  }
  return false;
}

bool Voxelize(const std::string& which, bool compute, Volumes& out)
{
  vtkNew<vtkRenderer> renderer;
  std::function<void(int)> step;
  if (!Build(which, renderer, step))
  {
    std::cerr << "unknown case " << which << std::endl;
    return false;
  }
  voxelgi_test::GIWindow view(renderer, 64, 96);
  view.GI->SetComputeVoxelization(compute);
  view.Window->Render();
  for (int frame = 1; step && frame <= 3; ++frame)
  {
    step(frame);
    view.Window->Render();
  }
  if (!view.GI->GetGIActive())
  {
    std::cerr << "GI did not run" << std::endl;
    return false;
  }
  out.Count = Values(view.GI, vtkVoxelGIPass::VOLUME_COUNT);
  out.Albedo = Values(view.GI, vtkVoxelGIPass::VOLUME_ALBEDO);
  out.Normal = Values(view.GI, vtkVoxelGIPass::VOLUME_NORMAL);
  out.Emission = Values(view.GI, vtkVoxelGIPass::VOLUME_EMISSION);
  out.Radiance = Values(view.GI, vtkVoxelGIPass::VOLUME_RADIANCE);
  out.SceneBytes = view.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SCENE_BUFFERS);
  renderer->SetPass(nullptr);
  view.GI->ReleaseGraphicsResources(view.Window);
  return !out.Count.empty() && out.Albedo.size() == 4 * out.Count.size();
}

/// Mean and largest absolute difference of 4-channel values (rgb only) over the voxels both
/// runs occupy.
void Differences(const Volumes& a, const Volumes& b, const std::vector<double> Volumes::*volume,
  double& mean, double& largest)
{
  double sum = 0.0;
  std::size_t n = 0;
  largest = 0.0;
  for (std::size_t v = 0; v < a.Count.size(); ++v)
  {
    if (a.Count[v] == 0.0 || b.Count[v] == 0.0)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs((a.*volume)[4 * v + c] - (b.*volume)[4 * v + c]);
      sum += d;
      largest = std::max(largest, d);
      ++n;
    }
  }
  mean = n ? sum / n : 0.0;
}
}

int TestVoxelComputePath(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "cornell";
  Volumes compute;
  Volumes raster;
  VOXELGI_CHECK(Voxelize(which, true, compute), "compute run");
  VOXELGI_CHECK(Voxelize(which, false, raster), "raster run");
  VOXELGI_CHECK(compute.SceneBytes > 0, "the compute run read no triangles");
  VOXELGI_CHECK(raster.SceneBytes == 0, "the raster run holds triangle buffers");
  VOXELGI_CHECK(compute.Count.size() == raster.Count.size(), "grids differ");

  std::size_t occupied = 0;
  std::size_t onlyOne = 0;
  std::size_t countsDiffer = 0;
  for (std::size_t v = 0; v < raster.Count.size(); ++v)
  {
    occupied += raster.Count[v] > 0.0 ? 1 : 0;
    onlyOne += (raster.Count[v] > 0.0) != (compute.Count[v] > 0.0) ? 1 : 0;
    countsDiffer += raster.Count[v] != compute.Count[v] ? 1 : 0;
  }
  double albedoMean = 0.0;
  double albedoMax = 0.0;
  double normalMean = 0.0;
  double normalMax = 0.0;
  Differences(compute, raster, &Volumes::Albedo, albedoMean, albedoMax);
  Differences(compute, raster, &Volumes::Normal, normalMean, normalMax);
  std::cout << which << ": " << occupied << " occupied voxels, " << onlyOne
            << " occupied by one path only, " << countsDiffer << " with other counts; albedo "
            << albedoMean << " mean, " << albedoMax << " largest levels off; normal " << normalMean
            << " mean, " << normalMax << " largest; scene buffers " << compute.SceneBytes
            << " bytes" << std::endl;
  VOXELGI_CHECK(occupied > 100, "too few voxels to compare");
  // Same rule, same float arithmetic but for the vertex transform (VTK's matrices against one
  // composed in double precision): llvmpipe gives identical voxels; allow rounding at ties.
  VOXELGI_CHECK(onlyOne <= occupied / 1000, onlyOne << " voxels occupied by one path only");
  VOXELGI_CHECK(countsDiffer <= occupied / 200, countsDiffer << " voxels with other counts");
  VOXELGI_CHECK(albedoMean <= 0.05 && albedoMax <= 2.0,
    "albedo " << albedoMean << " levels off on average, " << albedoMax << " at most");
  VOXELGI_CHECK(normalMean <= 0.05 && normalMax <= 2.0,
    "normal " << normalMean << " levels off on average, " << normalMax << " at most");
  // The lit voxels: shadow maps drawn from the resident triangles (compute) and through
  // copies of the mappers (raster) must shadow the same voxels.
  VOXELGI_CHECK(compute.Radiance.size() == raster.Radiance.size() && !raster.Radiance.empty(),
    "no radiance volume");
  double radianceMean = 0.0;
  double radianceMax = 0.0;
  Differences(compute, raster, &Volumes::Radiance, radianceMean, radianceMax);
  double radianceSum = 0.0;
  for (double value : raster.Radiance)
  {
    radianceSum += value;
  }
  const double radianceLevel = radianceSum / raster.Radiance.size();
  std::cout << "radiance: " << radianceMean << " mean, " << radianceMax
            << " largest difference; mean value " << radianceLevel << std::endl;
  VOXELGI_CHECK(radianceMean <= 0.01 * radianceLevel, "radiance differs by " << radianceMean << " on average");
  if (which == "emissive")
  {
    VOXELGI_CHECK(!compute.Emission.empty() && compute.Emission.size() == raster.Emission.size(),
      "no emission volume");
    double largest = 0.0;
    for (std::size_t i = 0; i < compute.Emission.size(); ++i)
    {
      largest = std::max(largest, std::abs(compute.Emission[i] - raster.Emission[i]));
    }
    std::cout << "emission: " << largest << " largest difference" << std::endl;
    VOXELGI_CHECK(largest <= 0.05, "emission differs by " << largest);
  }
  return EXIT_SUCCESS;
}
