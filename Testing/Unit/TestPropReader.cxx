// What the scan reads of a prop, without a GL context: inside a render (VTK's frustum
// culler has updated every visible prop's pipeline) an actor whose signature holds keeps
// the bounds read before; ahead of a render, without that culler, or for a follower, every
// read updates the pipeline; after VTK drew, a mapper VTK modified is read again.
#include "PropReader.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCullerCollection.h"
#include "vtkElevationFilter.h"
#include "vtkFollower.h"
#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

namespace
{
/// A renderer with one sphere centred at x = 0 drawn through a filter (so that moving the
/// source modifies neither the mapper's input nor its producer until the pipeline updates),
/// by a plain actor or a follower, and a reader of its props.
template <class ActorClass>
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<ActorClass> Actor;
  vtkNew<vtkSphereSource> Source;
  vtkNew<vtkElevationFilter> Filter;
  vtkNew<vtkOpenGLPolyDataMapper> Mapper;
  voxelgi::PropReader Reader;

  Scene()
  {
    this->Filter->SetInputConnection(this->Source->GetOutputPort());
    this->Mapper->SetInputConnection(this->Filter->GetOutputPort());
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
  }

  /// What the reader reads of the actor, inside a render or ahead of it.
  const voxelgi::PropReading& Read(bool inRender)
  {
    this->Reader.Begin(this->Renderer, inRender);
    const voxelgi::PropReading& reading = this->Reader.Read(this->Actor);
    this->Reader.End();
    return reading;
  }

  /// The x of the bounds' centre read.
  double CentreX(bool inRender)
  {
    const voxelgi::PropReading& reading = this->Read(inRender);
    EXPECT_TRUE(reading.HasBounds);
    return 0.5 * (reading.Bounds[0] + reading.Bounds[1]);
  }
};
}

TEST(PropReader, InsideARenderAnUnchangedSignatureKeepsTheBounds)
{
  Scene<vtkActor> scene;
  EXPECT_NEAR(scene.CentreX(true), 0.0, 1e-9);
  // Moved upstream, not updated: inside a render the culler would have updated it, so the
  // unchanged signature stands for unchanged bounds.
  scene.Source->SetCenter(2.0, 0.0, 0.0);
  EXPECT_NEAR(scene.CentreX(true), 0.0, 1e-9);
  // Once updated (as the culler does), the input's time changed: read again.
  scene.Actor->GetBounds();
  EXPECT_NEAR(scene.CentreX(true), 2.0, 1e-9);
  // The actor's own transform is in its signature.
  scene.Actor->SetPosition(1.0, 0.0, 0.0);
  EXPECT_NEAR(scene.CentreX(true), 3.0, 1e-9);
}

TEST(PropReader, AheadOfARenderOrWithoutACullerEveryReadUpdates)
{
  Scene<vtkActor> scene;
  EXPECT_NEAR(scene.CentreX(true), 0.0, 1e-9);
  scene.Source->SetCenter(2.0, 0.0, 0.0);
  EXPECT_NEAR(scene.CentreX(false), 2.0, 1e-9);
  scene.Renderer->GetCullers()->RemoveAllItems();
  scene.Source->SetCenter(4.0, 0.0, 0.0);
  EXPECT_NEAR(scene.CentreX(true), 4.0, 1e-9);
}

TEST(PropReader, AFollowerIsReadEveryFrame)
{
  Scene<vtkFollower> scene;
  scene.Actor->SetCamera(scene.Renderer->GetActiveCamera());
  EXPECT_NEAR(scene.CentreX(true), 0.0, 1e-9);
  scene.Source->SetCenter(2.0, 0.0, 0.0);
  EXPECT_NEAR(scene.CentreX(true), 2.0, 1e-9);
}

TEST(PropReader, WhatVTKModifiesWhileDrawingIsReadAfterTheDraw)
{
  Scene<vtkActor> scene;
  const vtkMTimeType scanned = scene.Read(true).Signature;
  EXPECT_EQ(voxelgi::PropReader::DrawnSignature(scene.Actor, scanned), scanned);
  // A mapper creates its default lookup table when it first draws.
  scene.Mapper->CreateDefaultLookupTable();
  const vtkMTimeType drawn = voxelgi::PropReader::DrawnSignature(scene.Actor, scanned);
  EXPECT_GT(drawn, scanned);
  EXPECT_EQ(drawn, voxelgi::PropReader::PropSignature(scene.Actor));
}
