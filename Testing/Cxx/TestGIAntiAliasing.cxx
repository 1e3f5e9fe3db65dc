// VTK's anti-aliasing with the pass, in a scene of what sci-vis images are full of: a line on
// a floor, 3D text, cube axes and glyph edges, lit by one light.
// Case "off": an 8x multisampled window, every GI term off (indirect light, AO, shadow and
// specular cones): the image equals plain VTK's within 2 levels at every pixel.
// Case "on": the same window at the defaults: edge pixels keep VTK's intermediate values.
// The edge pixels are those where VTK's 8 samples change plain VTK's one-sample image by more
// than 24 levels in a channel; at 80 % of them at least, GI's 8 samples must change GI's
// one-sample image the same way by at least 40 % as much; then the image is compared with
// its baseline.
// Case "unchanged": frames that show the same image again copy the last one back: the
// second unchanged frame draws no mapper, and its image equals the one VTK and the blend drew;
// after the window's sample count changes, the image equals a fresh pass's.
// Case "fxaa": a window without multisampling, the renderer's FXAA on: with every GI term off
// the image equals plain VTK's FXAA image within 2 levels; at the defaults GI runs and FXAA
// more than doubles the soft edge pixels of the window without it (pixels whose 3x3
// neighbourhood spans more than 48 levels in a channel and whose own value lies at least 12
// levels inside that span).
// Case "renderbuffers": the pass draws into an application's framebuffer of multisampled
// renderbuffers (no textures: Present blends with its quad instead of its dispatch): at the
// defaults its image equals the one drawn in VTK's own framebuffer within 2 levels, and GI
// changed it; with every GI term off it equals plain VTK's within 2 levels.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkConeSource.h"
#include "vtkCubeAxesActor.h"
#include "vtkGlyph3D.h"
#include "vtkLight.h"
#include "vtkLineSource.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderPass.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVectorText.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace
{
constexpr int Size = 200;

void BuildScene(vtkRenderer* renderer)
{
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-2, 0, -2), dvec3(-2, 0, 2), dvec3(2, 0, -2), 0.7, 0.7, 0.7);
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-1.8, 0.01, 1.2);
  line->SetPoint2(1.8, 0.01, 0.4);
  vtkActor* lineActor = vtkVoxelGIScenes::AddSource(renderer, line, 0.9, 0.1, 0.1);
  lineActor->GetProperty()->SetLineWidth(2.0);

  vtkNew<vtkVectorText> text;
  text->SetText("VTK 0.123");
  vtkNew<vtkTransform> place;
  place->Translate(-1.6, 0.05, -1.0);
  place->RotateY(15.0);
  place->Scale(0.45, 0.45, 0.45);
  vtkNew<vtkTransformPolyDataFilter> placed;
  placed->SetInputConnection(text->GetOutputPort());
  placed->SetTransform(place);
  vtkVoxelGIScenes::AddSource(renderer, placed, 0.1, 0.2, 0.8);

  vtkNew<vtkSphereSource> points; // glyphs at its vertices, along its normals
  points->SetCenter(0.8, 0.6, -0.2);
  points->SetRadius(0.5);
  points->SetThetaResolution(6);
  points->SetPhiResolution(4);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(8);
  cone->SetHeight(0.35);
  cone->SetRadius(0.12);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputConnection(points->GetOutputPort());
  glyphs->SetSourceConnection(cone->GetOutputPort());
  vtkVoxelGIScenes::AddSource(renderer, glyphs, 0.9, 0.8, 0.2);

  vtkNew<vtkCubeAxesActor> axes;
  axes->SetBounds(-2.0, 2.0, 0.0, 1.2, -2.0, 2.0);
  axes->SetCamera(renderer->GetActiveCamera());
  axes->SetFlyModeToOuterEdges();
  renderer->AddActor(axes);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 4.0, 3.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  renderer->SetBackground(0.15, 0.15, 0.2);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.2, 3.0, 5.0);
  camera->SetFocalPoint(0.0, 0.3, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.4);
}

vtkSmartPointer<vtkUnsignedCharArray> Pixels(vtkRenderWindow* window)
{
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  window->GetPixelData(0, 0, Size - 1, Size - 1, 0, pixels);
  return pixels;
}

int Channel(vtkUnsignedCharArray* image, int x, int y, int c)
{
  return image->GetValue(3 * (y * Size + x) + c);
}

/// The largest difference of any channel at any pixel.
int LargestDifference(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  int largest = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    largest = std::max(largest, std::abs(static_cast<int>(a->GetValue(i)) - b->GetValue(i)));
  }
  return largest;
}

/// The share of the pixels where `wide` (multisampled) differs from `narrow` (one sample) by
/// more than 24 levels in a channel at which `giWide` differs from `giNarrow` the same way, by
/// at least 40 % as much; `edges` gets the number of those pixels.
double KeptEdges(vtkUnsignedCharArray* wide, vtkUnsignedCharArray* narrow,
  vtkUnsignedCharArray* giWide, vtkUnsignedCharArray* giNarrow, int& edges)
{
  edges = 0;
  int kept = 0;
  for (vtkIdType p = 0; p < Size * Size; ++p)
  {
    int channel = 0, largest = 0;
    for (int c = 0; c < 3; ++c)
    {
      const int d = static_cast<int>(wide->GetValue(3 * p + c)) - narrow->GetValue(3 * p + c);
      if (std::abs(d) > std::abs(largest))
      {
        largest = d;
        channel = c;
      }
    }
    if (std::abs(largest) <= 24)
    {
      continue;
    }
    ++edges;
    const int d = static_cast<int>(giWide->GetValue(3 * p + channel)) -
      giNarrow->GetValue(3 * p + channel);
    kept += (d > 0) == (largest > 0) && std::abs(d) >= 0.4 * std::abs(largest) ? 1 : 0;
  }
  return edges > 0 ? static_cast<double>(kept) / edges : 0.0;
}

/// Pixels whose 3x3 neighbourhood spans more than 48 levels in a channel and whose own value
/// lies at least 12 levels inside it.
int EdgePixels(vtkUnsignedCharArray* image)
{
  int count = 0;
  for (int y = 1; y < Size - 1; ++y)
  {
    for (int x = 1; x < Size - 1; ++x)
    {
      bool edge = false;
      for (int c = 0; c < 3 && !edge; ++c)
      {
        int low = 255, high = 0;
        for (int j = -1; j <= 1; ++j)
        {
          for (int i = -1; i <= 1; ++i)
          {
            const int v = Channel(image, x + i, y + j, c);
            low = std::min(low, v);
            high = std::max(high, v);
          }
        }
        const int v = Channel(image, x, y, c);
        edge = high - low > 48 && v >= low + 12 && v <= high - 12;
      }
      count += edge ? 1 : 0;
    }
  }
  return count;
}

/// Draws its delegate into a framebuffer of renderbuffers of the window's size and samples,
/// as an application's own framebuffer may be, then blits it into the window's.
class RenderbufferPass : public vtkRenderPass
{
public:
  static RenderbufferPass* New();
  vtkTypeMacro(RenderbufferPass, vtkRenderPass);
  vtkRenderPass* Delegate = nullptr;

  void Render(const vtkRenderState* s) override
  {
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
    const int* size = window->GetSize();
    vtkOpenGLState* state = window->GetState();
    state->PushFramebufferBindings();
    if (!this->Framebuffer)
    {
      this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->Framebuffer->SetContext(window);
      this->Framebuffer->Bind();
      this->Framebuffer->PopulateFramebuffer(
        size[0], size[1], false, 1, VTK_UNSIGNED_CHAR, true, 24, window->GetMultiSamples());
    }
    this->Framebuffer->Bind();
    this->Framebuffer->ActivateDrawBuffer(0);
    this->Delegate->Render(s);
    this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
    state->PopFramebufferBindings();
    state->PushReadFramebufferBinding();
    this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
    this->Framebuffer->ActivateReadBuffer(0);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST);
    const int extent[4] = { 0, size[0], 0, size[1] };
    vtkOpenGLFramebufferObject::Blit(extent, extent, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    state->PopReadFramebufferBinding();
  }
  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(window);
    }
    this->Delegate->ReleaseGraphicsResources(window);
  }

private:
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
};
vtkStandardNewMacro(RenderbufferPass);

void TermsOff(vtkVoxelGIPass* gi)
{
  gi->SetIndirectIntensity(0.0);
  gi->SetAmbientOcclusionStrength(0.0);
  gi->SetConeShadows(false);
  gi->SetSpecularCone(false);
}
}

int TestGIAntiAliasing(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "off";
  vtkNew<vtkRenderer> renderer;
  BuildScene(renderer);
  const bool fxaa = which == "fxaa";
  voxelgi_test::GIWindow view(renderer, 64, Size, fxaa ? 0 : 8);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;

  if (fxaa)
  {
    view.RenderWithoutGI();
    const int aliased = EdgePixels(Pixels(window));
    renderer->UseFXAAOn();
    view.RenderWithoutGI();
    auto plain = Pixels(window);
    TermsOff(gi);
    window->Render();
    VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
    const int off = LargestDifference(plain, Pixels(window));
    std::cout << "FXAA, GI terms off: largest difference from plain VTK " << off << " levels"
              << std::endl;
    VOXELGI_CHECK(off <= 2, "the image differs from plain VTK's FXAA image");
    vtkNew<vtkVoxelGIPass> defaults;
    defaults->SetSoftwareProfileToOff();
    defaults->SetVoxelResolution(64);
    renderer->SetPass(defaults);
    window->Render();
    VOXELGI_CHECK(defaults->GetGIActive(), "GI did not run at the defaults");
    const int smoothed = EdgePixels(Pixels(window));
    std::cout << "edge pixels: " << aliased << " without FXAA, " << smoothed
              << " with FXAA and GI" << std::endl;
    VOXELGI_CHECK(smoothed > 2 * aliased, "FXAA did not smooth the GI image's edges");
    return voxelgi_test::ImageMatches(argc, argv, window);
  }

  if (which == "unchanged")
  {
    int draws = 0;
    vtkNew<vtkCallbackCommand> count;
    count->SetClientData(&draws);
    count->SetCallback([](vtkObject*, unsigned long, void* client, void*) { ++*static_cast<int*>(client); });
    vtkActor* text = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(2));
    VOXELGI_CHECK(text && text->GetMapper(), "no text actor");
    text->GetMapper()->AddObserver(vtkCommand::StartEvent, count);
    int drawn[3];
    vtkSmartPointer<vtkUnsignedCharArray> images[3];
    for (int frame = 0; frame < 3; ++frame)
    {
      draws = 0;
      window->Render();
      drawn[frame] = draws;
      images[frame] = Pixels(window);
    }
    std::cout << "text mapper draws: traced frame " << drawn[0] << ", first unchanged " << drawn[1]
              << ", second unchanged " << drawn[2] << std::endl;
    VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
    VOXELGI_CHECK(drawn[0] > 0 && drawn[1] > 0, "the mapper drew nothing");
    VOXELGI_CHECK(drawn[2] == 0, "the unchanged frame drew again instead of copying");
    const int off = LargestDifference(images[1], images[2]);
    std::cout << "copied image: largest difference " << off << " levels" << std::endl;
    VOXELGI_CHECK(off == 0, "the copied image differs from the drawn one");
    renderer->GetActiveCamera()->Azimuth(5.0);
    draws = 0;
    window->Render();
    VOXELGI_CHECK(draws > 0, "a camera move did not draw");
    // Only the window's sample count changes: VTK's framebuffer is new, the copy is not used
    // (VTK draws its samples again), and the image equals a fresh pass's in the same window
    // (both traced in full).
    gi->SetTemporalReuse(false);
    window->Render();
    window->Render();
    window->SetMultiSamples(2);
    draws = 0;
    window->Render();
    VOXELGI_CHECK(draws > 0, "a new sample count presented the old copy");
    auto resampled = Pixels(window);
    vtkNew<vtkVoxelGIPass> fresh;
    fresh->SetSoftwareProfileToOff();
    fresh->SetVoxelResolution(64);
    renderer->SetPass(fresh);
    window->Render();
    const int stale = LargestDifference(resampled, Pixels(window));
    std::cout << "after the sample count changed: largest difference from a fresh pass " << stale
              << " levels" << std::endl;
    VOXELGI_CHECK(stale <= 2, "the image after a sample-count change differs from a fresh pass's");
    return EXIT_SUCCESS;
  }

  view.RenderWithoutGI();
  auto plain = Pixels(window);
  if (which == "renderbuffers")
  {
    window->Render();
    VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
    auto own = Pixels(window);
    for (const bool on : { true, false })
    {
      vtkNew<vtkVoxelGIPass> application;
      application->SetSoftwareProfileToOff();
      application->SetVoxelResolution(64);
      if (!on)
      {
        TermsOff(application);
      }
      vtkNew<RenderbufferPass> wrapper;
      wrapper->Delegate = application;
      renderer->SetPass(wrapper);
      window->Render();
      VOXELGI_CHECK(application->GetGIActive(), "GI did not run in the renderbuffers");
      auto drawn = Pixels(window);
      const int off = LargestDifference(on ? own : plain, drawn);
      std::cout << (on ? "defaults: from the image in VTK's framebuffer "
                       : "GI terms off: from plain VTK ")
                << off << " levels" << std::endl;
      VOXELGI_CHECK(off <= 2, "the image in renderbuffers differs");
      if (on)
      {
        const int gain = LargestDifference(plain, drawn);
        std::cout << "defaults: from plain VTK " << gain << " levels" << std::endl;
        VOXELGI_CHECK(gain > 20, "GI did not change the image in renderbuffers");
      }
      renderer->SetPass(gi);
      wrapper->ReleaseGraphicsResources(window);
    }
    return EXIT_SUCCESS;
  }
  if (which == "off")
  {
    TermsOff(gi);
    window->Render();
    VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
    const int off = LargestDifference(plain, Pixels(window));
    std::cout << "GI terms off: largest difference from plain VTK " << off << " levels" << std::endl;
    VOXELGI_CHECK(off <= 2, "the image differs from plain VTK's 8x image");
    return EXIT_SUCCESS;
  }

  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  auto withGI = Pixels(window);
  window->SetMultiSamples(0);
  view.RenderWithoutGI();
  auto plainSingle = Pixels(window);
  window->Render();
  auto giSingle = Pixels(window);
  window->SetMultiSamples(8);
  window->Render();
  int edges = 0;
  const double kept = KeptEdges(plain, plainSingle, withGI, giSingle, edges);
  std::cout << "edge pixels of plain VTK: " << edges << ", kept by GI: " << 100.0 * kept << " %"
            << std::endl;
  VOXELGI_CHECK(edges > 200, "the scene has too few edges to measure");
  VOXELGI_CHECK(kept >= 0.8, "GI lost VTK's anti-aliased edges");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
