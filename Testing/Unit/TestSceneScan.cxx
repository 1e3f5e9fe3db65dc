// The Scan stage without a GL context: what it decides to rebuild for each kind of change,
// the update policies, the props it leaves out, and the key of an unchanged frame.
#include "Frame.h"
#include "FramePlan.h"
#include "Ranks.h"
#include "SceneScan.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkGlyph3DMapper.h"
#include "vtkNew.h"
#include "vtkOutlineSource.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
vtkSmartPointer<vtkActor> AddSphere(vtkRenderer* renderer, double x)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, 0.0, 0.0);
  sphere->Update();
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  mapper->SetInputData(sphere->GetOutput());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

struct ScanFixture : public ::testing::Test
{
  vtkNew<vtkRenderer> Renderer;
  voxelgi::SceneScan Scan;
  voxelgi::Settings Config;
  voxelgi::VoxelUpdate Update;
  voxelgi::ScanMessages Messages;
  voxelgi::Ranks OneProcess; // no controller: one process

  ScanFixture()
  {
    this->Config.VoxelResolution = 32;
    this->Config.GridPadding = 0.05;
    this->Config.UpdatePolicy = vtkVoxelGIPass::UPDATE_ON_CHANGE;
    this->Config.UpdateInterval = 3;
  }

  /// Scan; accept what it asks to rebuild (as the pass does after voxelizing).
  bool Next()
  {
    this->Messages = voxelgi::ScanMessages();
    const bool ok = this->Scan.Scan(
      this->Renderer, this->Config, this->OneProcess, this->Update, this->Messages);
    if (ok && this->Update.Run)
    {
      this->Scan.Accept(this->Update, this->Config);
    }
    return ok;
  }
};
}

TEST_F(ScanFixture, NothingToVoxelize)
{
  EXPECT_FALSE(this->Next());
  EXPECT_TRUE(this->Messages.Error.empty());
}

TEST_F(ScanFixture, FirstFrameRebuildsAllThenNothing)
{
  AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run);
  EXPECT_TRUE(this->Update.Full);
  EXPECT_FALSE(this->Update.Emission);
  EXPECT_EQ(this->Update.Grid.Resolution, 32);
  const double bounds[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  EXPECT_TRUE(this->Update.Grid.Covers(bounds));
  ASSERT_TRUE(this->Next());
  EXPECT_FALSE(this->Update.Run);
  EXPECT_EQ(this->Scan.GetRecords().size(), 1u);
}

TEST_F(ScanFixture, ChangedStaticActorRebuildsAllAndBecomesDynamic)
{
  auto a = AddSphere(this->Renderer, 0.0);
  AddSphere(this->Renderer, 2.0);
  ASSERT_TRUE(this->Next());
  a->GetProperty()->SetColor(1.0, 0.0, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run);
  EXPECT_TRUE(this->Update.Full);
  ASSERT_EQ(this->Scan.GetRecords().size(), 2u);
  EXPECT_TRUE(this->Scan.GetRecords()[0].Dynamic);
  EXPECT_FALSE(this->Scan.GetRecords()[1].Dynamic);
  // Changed again: now it is revoxelized alone.
  a->GetProperty()->SetColor(0.0, 1.0, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run);
  EXPECT_FALSE(this->Update.Full);
}

TEST_F(ScanFixture, ActorsChangedTogetherAllBecomeDynamicInOneRebuild)
{
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (int i = 0; i < 4; ++i)
  {
    actors.push_back(AddSphere(this->Renderer, 2.0 * i));
  }
  ASSERT_TRUE(this->Next());
  for (auto& actor : actors)
  {
    actor->AddPosition(0.0, 0.01, 0.0);
  }
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Full);
  for (const voxelgi::ActorRecord& record : this->Scan.GetRecords())
  {
    EXPECT_TRUE(record.Dynamic);
  }
  // Moved together again: the dynamic actors alone are revoxelized.
  for (auto& actor : actors)
  {
    actor->AddPosition(0.0, -0.01, 0.0);
  }
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run);
  EXPECT_FALSE(this->Update.Full);
}

TEST_F(ScanFixture, WithoutAutoDynamicEveryChangeIsFull)
{
  this->Config.AutoDynamic = false;
  auto a = AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  for (int i = 0; i < 2; ++i)
  {
    a->GetProperty()->SetColor(0.1 * i, 0.0, 0.0);
    ASSERT_TRUE(this->Next());
    EXPECT_TRUE(this->Update.Full);
    EXPECT_FALSE(this->Scan.GetRecords()[0].Dynamic);
  }
}

TEST_F(ScanFixture, UserDynamicActorIsRevoxelizedAlone)
{
  auto a = AddSphere(this->Renderer, 0.0);
  AddSphere(this->Renderer, 2.0);
  vtkVoxelGIPass::SetPropDynamic(a, true);
  ASSERT_TRUE(this->Next());
  a->SetPosition(0.1, 0.0, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run);
  EXPECT_FALSE(this->Update.Full);
}

TEST_F(ScanFixture, AddedActorAndLeavingTheGridRebuildAll)
{
  auto a = AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  AddSphere(this->Renderer, 0.5);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Full);
  const voxelgi::VoxelGrid before = this->Scan.GetGrid();
  vtkVoxelGIPass::SetPropDynamic(a, true);
  ASSERT_TRUE(this->Next());
  a->SetPosition(10.0, 0.0, 0.0); // outside the grid: refit, full rebuild
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Full);
  EXPECT_GT(this->Scan.GetGrid().Size(), before.Size());
}

TEST_F(ScanFixture, FirstEmitterRebuildsAll)
{
  auto a = AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_FALSE(this->Update.Emission);
  vtkVoxelGIPass::SetPropEmission(a, 2.0, 4.0, 1.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Full); // the emission channels are allocated: everything again
  EXPECT_TRUE(this->Update.Emission);
}

TEST_F(ScanFixture, OnDemandWaitsForInvalidate)
{
  this->Config.UpdatePolicy = vtkVoxelGIPass::UPDATE_ON_DEMAND;
  auto a = AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run); // the first frame always builds
  a->GetProperty()->SetColor(1.0, 0.0, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_FALSE(this->Update.Run);
  this->Scan.Invalidate();
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run);
  EXPECT_TRUE(this->Update.Full);
}

TEST_F(ScanFixture, EveryNFramesPicksUpChangesAtTheInterval)
{
  this->Config.UpdatePolicy = vtkVoxelGIPass::UPDATE_EVERY_N_FRAMES;
  auto a = AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  a->GetProperty()->SetColor(1.0, 0.0, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_FALSE(this->Update.Run);
  ASSERT_TRUE(this->Next());
  EXPECT_FALSE(this->Update.Run);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Run); // third frame after the last update
}

TEST_F(ScanFixture, EveryFrameRebuildsAll)
{
  this->Config.UpdatePolicy = vtkVoxelGIPass::UPDATE_EVERY_FRAME;
  AddSphere(this->Renderer, 0.0);
  for (int i = 0; i < 3; ++i)
  {
    ASSERT_TRUE(this->Next());
    EXPECT_TRUE(this->Update.Run);
    EXPECT_TRUE(this->Update.Full);
  }
}

TEST_F(ScanFixture, VoxelSettingsRebuildWhateverThePolicy)
{
  this->Config.UpdatePolicy = vtkVoxelGIPass::UPDATE_ON_DEMAND;
  AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  this->Config.VoxelResolution = 64;
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Update.Full);
  EXPECT_EQ(this->Update.Grid.Resolution, 64);
}

/// A translucent sphere at x whose triangles the shadows cannot read (a backface property).
void AddUnreadableTranslucentSphere(vtkRenderer* renderer, double x)
{
  vtkActor* actor = AddSphere(renderer, x);
  actor->GetProperty()->SetOpacity(0.2);
  vtkNew<vtkProperty> back;
  actor->SetBackfaceProperty(back);
}

TEST_F(ScanFixture, TranslucentCastsAndTheUnreadableAreLeftOutWithNoticesThatCount)
{
  AddSphere(this->Renderer, 0.0);
  AddSphere(this->Renderer, 2.0)->GetProperty()->SetOpacity(0.5);
  AddSphere(this->Renderer, 4.0)->GetProperty()->SetRepresentationToWireframe();
  ASSERT_TRUE(this->Next());
  // The translucent sphere casts shadows that pass part of the light (not voxelized).
  ASSERT_EQ(this->Scan.GetRecords().size(), 2u);
  EXPECT_FALSE(this->Scan.GetRecords()[0].Translucent);
  EXPECT_TRUE(this->Scan.GetRecords()[1].Translucent);
  ASSERT_EQ(this->Messages.Warnings.size(), 1u);
  EXPECT_EQ(this->Messages.Warnings[0],
    "Rendered by VTK without voxel GI: 1 x vtkOpenGLActor (wireframe representation).");
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Messages.Warnings.empty()); // said once
  AddUnreadableTranslucentSphere(this->Renderer, 6.0);
  ASSERT_TRUE(this->Next());
  ASSERT_EQ(this->Messages.Warnings.size(), 1u);
  EXPECT_EQ(this->Messages.Warnings[0],
    "Rendered by VTK without voxel GI: 1 x vtkOpenGLActor (translucent, a backface property).");
  AddUnreadableTranslucentSphere(this->Renderer, 8.0);
  ASSERT_TRUE(this->Next());
  ASSERT_EQ(this->Messages.Warnings.size(), 1u); // the count of a kind doubled: said again
  EXPECT_EQ(this->Messages.Warnings[0],
    "Rendered by VTK without voxel GI: 2 x vtkOpenGLActor (translucent, a backface property).");
  AddUnreadableTranslucentSphere(this->Renderer, 10.0);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Messages.Warnings.empty()); // 3 of a kind said at 2
  AddUnreadableTranslucentSphere(this->Renderer, 12.0);
  ASSERT_TRUE(this->Next());
  ASSERT_EQ(this->Messages.Warnings.size(), 1u);
  EXPECT_EQ(this->Messages.Warnings[0],
    "Rendered by VTK without voxel GI: 4 x vtkOpenGLActor (translucent, a backface property).");
}

TEST_F(ScanFixture, SplatsOfAShapeAreVoxelizedAndGaussianOnesSaid)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  auto add = [&](const char* shape) {
    vtkNew<vtkPointGaussianMapper> mapper;
    mapper->SetInputData(sphere->GetOutput());
    mapper->SetScaleFactor(0.1);
    mapper->SetSplatShaderCode(shape);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    this->Renderer->AddActor(actor);
  };
  add("//VTK::Color::Impl\n"); // a splat shape: spheres
  add(nullptr);                 // VTK's Gaussian blobs: no surface
  ASSERT_TRUE(this->Next());
  ASSERT_EQ(this->Scan.GetRecords().size(), 1u); // the shaped splats, through their proxy
  ASSERT_EQ(this->Messages.Warnings.size(), 1u);
  EXPECT_NE(this->Messages.Warnings[0].find(
              "1 x vtkOpenGLActor with a vtkOpenGLPointGaussianMapper (Gaussian splats"),
    std::string::npos)
    << this->Messages.Warnings[0];
}

TEST_F(ScanFixture, OutlineInWireframeNeedsNoNotice)
{
  // ParaView's outline representation: a box of lines in a wireframe actor.
  AddSphere(this->Renderer, 0.0);
  vtkNew<vtkOutlineSource> outline;
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  mapper->SetInputConnection(outline->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToWireframe();
  this->Renderer->AddActor(actor);
  ASSERT_TRUE(this->Next());
  EXPECT_EQ(this->Scan.GetRecords().size(), 2u); // kept as plain lines are: nothing to rasterize
  EXPECT_TRUE(this->Messages.Warnings.empty());
}

TEST_F(ScanFixture, GlyphMappersAreVoxelized)
{
  vtkNew<vtkSphereSource> source;
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputConnection(source->GetOutputPort());
  glyphs->SetSourceConnection(source->GetOutputPort());
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphs);
  this->Renderer->AddActor(glyphActor);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Messages.Warnings.empty());
  EXPECT_EQ(this->Scan.GetRecords().size(), 1u);
}

TEST_F(ScanFixture, NonFinitePointsAreReported)
{
  auto a = AddSphere(this->Renderer, 0.0);
  auto* poly = vtkPolyData::SafeDownCast(a->GetMapper()->GetInputDataObject(0, 0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  poly->GetPoints()->SetPoint(0, nan, 0.0, 0.0);
  poly->Modified();
  this->Next();
  bool reported = false;
  for (const std::string& w : this->Messages.Warnings)
  {
    reported = reported || w.find("NaN or Inf") != std::string::npos;
  }
  EXPECT_TRUE(reported);
}

TEST_F(ScanFixture, SpecularMaterialsAreNoticed)
{
  auto a = AddSphere(this->Renderer, 0.0);
  ASSERT_TRUE(this->Next());
  EXPECT_FALSE(this->Scan.GetAnySpecular());
  a->GetProperty()->SetSpecular(0.5);
  ASSERT_TRUE(this->Next());
  EXPECT_TRUE(this->Scan.GetAnySpecular());
}

TEST_F(ScanFixture, ImageKeyPlansTheTrace)
{
  vtkActor* sphere = AddSphere(this->Renderer, 0.0);
  this->Renderer->GetActiveCamera(); // created on first use, as VTK does before the pass runs
  voxelgi::FrameHistory history;
  const voxelgi::RadianceState radiance;
  const auto plan = [&](vtkMTimeType settingsTime) {
    return history.PlanTrace(
      radiance, false, settingsTime, this->Scan.ImageKey(this->Renderer, settingsTime, false));
  };
  const auto traced = [&](vtkMTimeType settingsTime) {
    history.Traced(radiance, settingsTime, this->Scan.ImageKey(this->Renderer, settingsTime, false));
  };
  EXPECT_EQ(plan(1), voxelgi::TraceWork::Full); // nothing traced yet
  traced(1);
  EXPECT_EQ(plan(1), voxelgi::TraceWork::Present);
  EXPECT_EQ(plan(2), voxelgi::TraceWork::Full); // the pass's settings changed
  traced(2);
  this->Renderer->GetActiveCamera()->Azimuth(10.0);
  EXPECT_EQ(plan(2), voxelgi::TraceWork::CameraOnly);
  traced(2);
  EXPECT_EQ(plan(2), voxelgi::TraceWork::Present);
  sphere->AddPosition(1.0, 0.0, 0.0);
  EXPECT_EQ(plan(2), voxelgi::TraceWork::CameraOnly); // a prop moved: the key differs
  traced(2);
  EXPECT_EQ(history.PlanTrace(radiance, true, 2, this->Scan.ImageKey(this->Renderer, 2, false)),
    voxelgi::TraceWork::Full); // this renderer's lights changed other than by turning
  history.NotTraced();
  EXPECT_EQ(plan(2), voxelgi::TraceWork::Full);
}

namespace
{
voxelgi::VoxelGrid Grid(int resolution, double x = 0.0)
{
  voxelgi::VoxelGrid grid;
  grid.Origin = glm::dvec3(x, 0.0, 0.0);
  grid.VoxelSize = 1.0;
  grid.Resolution = resolution;
  return grid;
}
}

TEST(FrameHistory, PlansTheLights)
{
  voxelgi::Settings settings;
  settings.CameraLightTurn = 45.0;
  voxelgi::FrameHistory history;
  const double inf = std::numeric_limits<double>::infinity();
  const voxelgi::VoxelGrid g = Grid(64);
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, g, false), voxelgi::LightWork::Relight);
  history.Lit(voxelgi::LightWork::Relight, true, settings, g);
  const unsigned long long lit = history.GetRadiance().Generation;
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, g, false), voxelgi::LightWork::Current);
  EXPECT_EQ(history.PlanLights(false, true, 30.0, settings, g, false), voxelgi::LightWork::Current);
  EXPECT_EQ(history.PlanLights(false, true, 60.0, settings, g, false), voxelgi::LightWork::Continue);
  EXPECT_EQ(history.PlanLights(false, true, inf, settings, g, false), voxelgi::LightWork::Relight);
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, Grid(128), false), voxelgi::LightWork::Relight);
  history.Lit(voxelgi::LightWork::Continue, true, settings, g);
  EXPECT_EQ(history.GetRadiance().Generation, lit); // a camera-light turn keeps the trace's
  EXPECT_EQ(history.PlanLights(true, false, 0.0, settings, g, false), voxelgi::LightWork::Relight);
  history.VoxelsWritten();
  EXPECT_EQ(history.PlanLights(false, true, 60.0, settings, g, false), voxelgi::LightWork::Relight);
  history.Lit(voxelgi::LightWork::Relight, false, settings, g);
  EXPECT_EQ(history.GetRadiance().Generation, lit + 1);
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, g, false), voxelgi::LightWork::Relight);
}

TEST(FrameHistory, InteractiveRelightsConvergeWhenStill)
{
  voxelgi::Settings settings;
  settings.Bounces = 4;
  voxelgi::FrameHistory history;
  const double inf = std::numeric_limits<double>::infinity();
  const voxelgi::VoxelGrid g = Grid(64);
  // Nothing to continue from yet.
  EXPECT_EQ(history.PlanLights(false, true, inf, settings, g, true), voxelgi::LightWork::Relight);
  history.Lit(voxelgi::LightWork::Relight, true, settings, g);
  const unsigned long long lit = history.GetRadiance().Generation;
  // A light or an actor changes while VTK renders interactively: one bounce on.
  EXPECT_EQ(history.PlanLights(false, true, inf, settings, g, true), voxelgi::LightWork::Progress);
  EXPECT_EQ(history.PlanLights(true, false, 0.0, settings, g, true), voxelgi::LightWork::Progress);
  EXPECT_EQ(history.PlanLights(true, false, 0.0, settings, Grid(64, 0.5), true),
    voxelgi::LightWork::Relight); // the grid moved: the last solution is elsewhere
  history.Lit(voxelgi::LightWork::Progress, true, settings, g);
  EXPECT_EQ(history.GetRadiance().Generation, lit + 1); // the image is traced anew
  // Interaction goes on without a change: nothing to do; the first still frame converges.
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, g, true), voxelgi::LightWork::Current);
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, g, false), voxelgi::LightWork::Relight);
  history.Lit(voxelgi::LightWork::Relight, true, settings, g);
  EXPECT_EQ(history.PlanLights(false, false, 0.0, settings, g, false), voxelgi::LightWork::Current);
  // One bounce is all a relight runs anyway.
  settings.Bounces = 1;
  history.Lit(voxelgi::LightWork::Relight, true, settings, g);
  EXPECT_EQ(history.PlanLights(false, true, inf, settings, g, true), voxelgi::LightWork::Relight);
}
