// Which surfaces need their triangles' planes in the G-buffer: a sphere with point normals
// leans off its triangles; a box, a plane, a sphere without normals or shaded flat does not;
// the answer follows the input when it changes.
#include "FacetNeed.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkGlyph3DMapper.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

namespace
{
/// Whether an actor drawing `source`'s output needs the planes.
bool Needs(voxelgi::FacetNeed& need, vtkAlgorithm* source, bool flat = false)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->Update();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  if (flat)
  {
    actor->GetProperty()->SetInterpolationToFlat();
  }
  return need.Needs(actor);
}
}

TEST(FacetNeed, SmoothSphereNeedsThePlanes)
{
  voxelgi::FacetNeed need;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  EXPECT_TRUE(Needs(need, sphere));
  EXPECT_FALSE(Needs(need, sphere, true)) << "shaded flat: VTK uses each triangle's plane";
}

TEST(FacetNeed, NormalsOfTheFacesDoNot)
{
  voxelgi::FacetNeed need;
  vtkNew<vtkCubeSource> cube;
  EXPECT_FALSE(Needs(need, cube));
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 4);
  EXPECT_FALSE(Needs(need, plane));
  vtkNew<vtkSphereSource> bare;
  bare->GenerateNormalsOff();
  EXPECT_FALSE(Needs(need, bare)) << "without normals VTK shades each triangle's plane";
}

TEST(FacetNeed, FollowsTheInput)
{
  voxelgi::FacetNeed need;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  mapper->Update();
  EXPECT_TRUE(need.Needs(actor));
  sphere->GenerateNormalsOff();
  mapper->Update();
  EXPECT_FALSE(need.Needs(actor));
}

TEST(FacetNeed, UnreadableActorsNeedThem)
{
  voxelgi::FacetNeed need;
  vtkNew<vtkGlyph3DMapper> glyphs;
  vtkNew<vtkActor> actor;
  actor->SetMapper(glyphs);
  EXPECT_TRUE(need.Needs(actor));
  EXPECT_TRUE(need.Needs(nullptr));
}
